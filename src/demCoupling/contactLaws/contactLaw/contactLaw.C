/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "contactLaw.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(contactLaw, 0);
    defineRunTimeSelectionTable(contactLaw, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::contactLaw::getInRange
(
    const dictionary& dict,
    const word& key,
    const scalar defaultValue,
    const scalar lower,
    const scalar upper
)
{
    return inputChecks::getInRange(dict, key, defaultValue, lower, upper);
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "permeabilityModel.H"
#include "inputChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(permeabilityModel, 0);
    defineRunTimeSelectionTable(permeabilityModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::permeabilityModel::permeabilityModel
(
    const dictionary& dict,
    const wordList& entryNames
)
:
    dict_(inputChecks::checkModelEntries(dict, entryNames))
{}


// ************************************************************************* //

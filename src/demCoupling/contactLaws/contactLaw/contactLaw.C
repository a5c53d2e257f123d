/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "contactLaw.H"

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
    const scalar value = dict.getOrDefault<scalar>(key, defaultValue);

    if (!(value >= lower && value <= upper))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' in " << dict.name();
        if (upper < GREAT)
        {
            FatalIOError
                << " must lie in [" << lower << ", " << upper << "]";
        }
        else
        {
            FatalIOError << " must be >= " << lower;
        }
        FatalIOError << ", found " << value << nl << exit(FatalIOError);
    }

    return value;
}


// ************************************************************************* //

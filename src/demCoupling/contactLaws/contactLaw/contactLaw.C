/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "contactLaw.H"
#include "OStringStream.H"

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
        OStringStream rule;
        if (upper < GREAT)
        {
            rule<< "must lie in [" << lower << ", " << upper << "]";
        }
        else
        {
            rule<< "must be >= " << lower;
        }
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' in " << dict.name() << " "
            << rule.str().c_str() << ", found " << value << nl
            << exit(FatalIOError);
    }

    return value;
}


// ************************************************************************* //

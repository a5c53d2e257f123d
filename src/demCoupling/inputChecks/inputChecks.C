/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "inputChecks.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

namespace
{

//- value if it is > 0, else a FatalIOError naming the entry
Foam::scalar positiveOrStop
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Foam::scalar value
)
{
    using namespace Foam;

    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' in " << dict.name()
            << " must be > 0, found " << value << nl
            << exit(FatalIOError);
    }

    return value;
}

} // End anonymous namespace


Foam::scalar Foam::inputChecks::getPositive
(
    const dictionary& dict,
    const word& key
)
{
    return positiveOrStop(dict, key, dict.get<scalar>(key));
}


Foam::scalar Foam::inputChecks::getInOpenRange
(
    const dictionary& dict,
    const word& key,
    const scalar lower,
    const scalar upper
)
{
    const scalar value = dict.get<scalar>(key);

    if (!(value > lower && value < upper))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' in " << dict.name()
            << " must lie in (" << lower << ", " << upper << "), found "
            << value << nl
            << exit(FatalIOError);
    }

    return value;
}


Foam::scalar Foam::inputChecks::getPositiveOrDefault
(
    const dictionary& dict,
    const word& key,
    const scalar defaultValue
)
{
    return positiveOrStop
    (
        dict,
        key,
        dict.getOrDefault<scalar>(key, defaultValue)
    );
}


Foam::scalar Foam::inputChecks::getInRange
(
    const dictionary& dict,
    const word& key,
    const scalar defaultValue,
    const scalar lower,
    const scalar upper
)
{
    return getInInterval(dict, key, defaultValue, lower, upper, false, false);
}


Foam::scalar Foam::inputChecks::getInInterval
(
    const dictionary& dict,
    const word& key,
    const scalar defaultValue,
    const scalar lower,
    const scalar upper,
    const bool lowerOpen,
    const bool upperOpen
)
{
    const scalar value = dict.getOrDefault<scalar>(key, defaultValue);

    const bool aboveLower = lowerOpen ? value > lower : value >= lower;
    const bool belowUpper = upperOpen ? value < upper : value <= upper;
    if (!(aboveLower && belowUpper))
    {
        // Ten digits: limits as a user writes them (-273.15, not
        // -273.14999999999998 at a case's writePrecision 17)
        OStringStream rule;
        rule.precision(10);
        if (upper < GREAT)
        {
            rule<< "must lie in " << (lowerOpen ? "(" : "[") << lower << ", "
                << upper << (upperOpen ? ")" : "]");
        }
        else
        {
            rule<< "must be " << (lowerOpen ? "> " : ">= ") << lower;
        }
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' in " << dict.name() << " "
            << rule.str().c_str() << ", found " << value << nl
            << exit(FatalIOError);
    }

    return value;
}


namespace
{

Foam::dimensionedScalar getChecked
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Foam::dimensionSet& dims,
    const bool allowZero
)
{
    using namespace Foam;
    if (!dict.found(key))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' not found in " << dict.name()
            << "; expected '" << key << " " << dims << " <value>;'" << nl
            << exit(FatalIOError);
    }

    dimensionedScalar value(key, dims, dict);

    if (!(value.value() > 0 || (allowZero && value.value() == 0)))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' in " << dict.name()
            << (allowZero ? " must be >= 0" : " must be > 0") << ", found "
            << value.value() << nl
            << exit(FatalIOError);
    }

    return value;
}

} // End anonymous namespace


Foam::dimensionedScalar Foam::inputChecks::getPositive
(
    const dictionary& dict,
    const word& key,
    const dimensionSet& dims
)
{
    return getChecked(dict, key, dims, false);
}


Foam::dimensionedScalar Foam::inputChecks::getNonNegative
(
    const dictionary& dict,
    const word& key,
    const dimensionSet& dims
)
{
    return getChecked(dict, key, dims, true);
}


// ************************************************************************* //

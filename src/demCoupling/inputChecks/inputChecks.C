/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "inputChecks.H"
#include "OStringStream.H"

#include <algorithm>
#include <cctype>
#include <vector>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

namespace
{

//- Levenshtein distance of a and b (insertions, deletions and
//- substitutions), letters compared case-insensitively
std::size_t editDistance(const std::string& a, const std::string& b)
{
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
    {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
        {
            const std::size_t above = row[j];
            const bool same =
                std::tolower(static_cast<unsigned char>(a[i - 1]))
             == std::tolower(static_cast<unsigned char>(b[j - 1]));
            row[j] = std::min
            ({
                row[j] + 1,
                row[j - 1] + 1,
                diagonal + (same ? 0 : 1)
            });
            diagonal = above;
        }
    }
    return row[b.size()];
}

} // End anonymous namespace


Foam::word Foam::inputChecks::closestName
(
    const word& key,
    const wordList& validNames
)
{
    word best;
    std::size_t bestDistance = std::string::npos;
    for (const word& name : validNames)
    {
        // A third of the name's letters, 1 to 3 edits: neighborSkin is
        // neighbourSkin, but k is not d
        const std::size_t limit =
            std::min<std::size_t>(3, std::max<std::size_t>(1, name.size()/3));
        const std::size_t d = editDistance(key, name);
        if (d <= limit && d < bestDistance)
        {
            best = name;
            bestDistance = d;
        }
    }
    return best;
}


Foam::string Foam::inputChecks::shortForm(const scalar value)
{
    OStringStream os;
    os.precision(6);
    os<< value;
    return os.str();
}


const Foam::dictionary& Foam::inputChecks::checkKnownEntries
(
    const dictionary& dict,
    const wordList& validNames
)
{
    for (const entry& e : dict)
    {
        const word& key = e.keyword();
        if
        (
            validNames.found(key)
         || key == "FoamFile"
         || (!key.empty() && key[0] == '#')
        )
        {
            continue;
        }

        // A sub-dictionary's name is the file's path and its scope,
        // '.'-separated (.../constant/demProperties.walls.bottom); split
        // after the path's last '/' (a copy, as a function object gets
        // its dictionary, has no parent to ask for the file)
        const std::string& scoped = dict.name();
        const std::size_t slash = scoped.rfind('/');
        const std::size_t dot =
            scoped.find('.', slash == std::string::npos ? 0 : slash);
        const string file(scoped.substr(0, dot));
        string scope;
        if (dot != std::string::npos)
        {
            scope = scoped.substr(dot + 1);
            scope.replaceAll(".", "/");
        }

        // The entry's own line (an empty sub-dictionary has none: its
        // dictionary's)
        label line = e.startLineNumber();
        if (line < 0)
        {
            line = dict.startLineNumber();
        }

        OStringStream message;
        message<< "Unknown entry '" << key.c_str() << "'";
        if (!scope.empty())
        {
            message<< " in '" << scope.c_str() << "'";
        }
        message<< " at line " << line << " of " << file.c_str();
        const word guess(closestName(key, validNames));
        if (!guess.empty())
        {
            message<< "; did you mean '" << guess.c_str() << "'?";
        }
        message<< nl << "Valid entries" << (scope.empty() ? "" : " of '")
            << scope.c_str() << (scope.empty() ? "" : "'") << ":";
        for (const word& name : validNames)
        {
            message<< ' ' << name.c_str();
        }

        // The header as OpenFOAM's own errors write it (the scoped name)
        FatalIOError
        (
            FUNCTION_NAME,
            __FILE__,
            __LINE__,
            dict.name(),
            line,
            e.endLineNumber() < 0 ? line : e.endLineNumber()
        )   << message.str().c_str() << nl << exit(FatalIOError);
    }

    return dict;
}


const Foam::wordList& Foam::inputChecks::functionObjectEntryNames()
{
    // functionObject, functionObjectList, timeControl (write..., execute...
    // and the older output... controls), timeControlFunctionObject,
    // regionFunctionObject, writeFile
    static const wordList names
    ({
        "type", "libs", "functionObjectLibs", "enabled", "log", "region",
        "subRegion", "timeStart", "timeEnd", "triggerStart", "triggerEnd",
        "controlMode", "deltaTCoeff", "nStepsToStartTimeChange",
        "writeControl", "writeInterval", "executeControl", "executeInterval",
        "outputControl", "outputInterval", "writePrecision", "writeToFile",
        "useUserTime"
    });
    return names;
}


const Foam::dictionary& Foam::inputChecks::checkModelEntries
(
    const dictionary& dict,
    const wordList& entryNames
)
{
    wordList names(1, word("type"));
    names.append(entryNames);
    return checkKnownEntries(dict, names);
}


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
            << " must be > 0, found " << inputChecks::shortForm(value).c_str()
            << nl
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
            << " must lie in (" << shortForm(lower).c_str() << ", "
            << shortForm(upper).c_str() << "), found "
            << shortForm(value).c_str() << nl
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
        // Six digits: limits as a user writes them (-273.15, not
        // -273.14999999999998 at a case's writePrecision 17)
        OStringStream rule;
        rule.precision(6);
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
            << rule.str().c_str() << ", found " << shortForm(value).c_str()
            << nl
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
            << inputChecks::shortForm(value.value()).c_str() << nl
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

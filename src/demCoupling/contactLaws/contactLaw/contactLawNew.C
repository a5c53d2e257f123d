/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "contactLaw.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::contactLaw> Foam::contactLaw::New(const dictionary& dict)
{
    // A case written before the family existed has no 'type': say what to
    // add rather than only that an entry is missing
    if (!dict.found("type"))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'type' not found in " << dict.name()
            << ": name the contact law, one of "
            << dictionaryConstructorTablePtr_->sortedToc()
            << " (the spring-dashpot law of earlier cases is"
            << " 'type linearSpring;')" << nl << exit(FatalIOError);
    }

    const word lawType(dict.get<word>("type"));

    Info<< "    contact law " << lawType << " (" << dict.dictName() << ")"
        << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(lawType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "contact law",
            lawType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<contactLaw>(cstrIter()(dict));
}


// ************************************************************************* //

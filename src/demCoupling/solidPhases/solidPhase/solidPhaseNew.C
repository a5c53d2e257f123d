/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "solidPhase.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::solidPhase> Foam::solidPhase::New
(
    const fvMesh& mesh,
    const dictionary& darcyProperties
)
{
    const dictionary& dict = darcyProperties.subDict("solidPhase");
    const word modelType(dict.get<word>("type"));

    Info<< "Selecting solid phase " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "solid phase",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<solidPhase>(cstrIter()(mesh, dict));
}


// ************************************************************************* //

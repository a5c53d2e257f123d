/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "permeabilityModel.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::permeabilityModel> Foam::permeabilityModel::New
(
    const dictionary& darcyProperties
)
{
    const dictionary& dict = darcyProperties.subDict("permeability");
    const word modelType(dict.get<word>("type"));

    Info<< "Selecting permeability model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "permeability model",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<permeabilityModel>(cstrIter()(dict));
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "pressureSintering.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bondSinteringModels
{
    defineTypeNameAndDebug(pressureSintering, 0);
    addToRunTimeSelectionTable(bondSinteringModel, pressureSintering, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bondSinteringModels::pressureSintering::pressureSintering(const dictionary& dict)
:
    bondSinteringModel(dict, wordList())
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bondSinteringModels::pressureSintering::set(dem::BondParameters& bonds) const
{
    bonds.sintering = dem::BondSintering::pressureSintering;
}


// ************************************************************************* //

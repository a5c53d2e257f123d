/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "permeabilityModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(permeabilityModel, 0);
    defineRunTimeSelectionTable(permeabilityModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::permeabilityModel::permeabilityModel(const dictionary& dict)
:
    dict_(dict)
{}


// ************************************************************************* //

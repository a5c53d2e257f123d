/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "kozenyCarmanGrainSize.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace permeabilityModels
{
    defineTypeNameAndDebug(kozenyCarmanGrainSize, 0);
    addToRunTimeSelectionTable
    (
        permeabilityModel,
        kozenyCarmanGrainSize,
        dictionary
    );
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::permeabilityModels::kozenyCarmanGrainSize::kozenyCarmanGrainSize
(
    const dictionary& dict
)
:
    kozenyCarman
    (
        dict,
        "d",
        [](const dictionary& d)
        {
            return sqr(inputChecks::getPositive(d, "d"))/180.0;
        }
    )
{}


// ************************************************************************* //

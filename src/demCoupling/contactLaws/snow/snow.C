/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "snow.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace contactLaws
{
    defineTypeNameAndDebug(snow, 0);
    addToRunTimeSelectionTable(contactLaw, snow, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactLaws::snow::snow(const dictionary& dict)
:
    contactLaw
    (
        dict,
        {
            "youngsModulus", "tangentialToNormalStiffness",
            "normalDampingRatio", "tangentialDampingRatio", "friction"
        }
    )
{
    material_.law = dem::ContactLaw::snow;
    material_.youngsModulus = inputChecks::getPositive(dict, "youngsModulus");
    material_.tangentialToNormalStiffness =
        getInRange(dict, "tangentialToNormalStiffness", 0.6, 0, 1);
    material_.normalDampingRatio =
        getInRange(dict, "normalDampingRatio", 0, 0, 1);
    material_.tangentialDampingRatio =
        getInRange(dict, "tangentialDampingRatio", 0, 0, 1);
    material_.friction = getInRange(dict, "friction", 0, 0);

    // The pair's constants come from E and the radii: the linear spring's
    // own entries stay unused (zero, so that nothing reads a default)
    material_.normalStiffness = 0;
    material_.tangentialStiffness = 0;
    material_.normalDamping = 0;
    material_.tangentialDamping = 0;
}


// ************************************************************************* //

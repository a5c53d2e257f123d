/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "linearSpring.H"
#include "inputChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace contactLaws
{
    defineTypeNameAndDebug(linearSpring, 0);
    addToRunTimeSelectionTable(contactLaw, linearSpring, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactLaws::linearSpring::linearSpring(const dictionary& dict)
:
    contactLaw
    (
        dict,
        {
            "normalStiffness", "tangentialStiffness", "normalDamping",
            "tangentialDamping", "friction"
        }
    )
{
    material_.law = dem::ContactLaw::linearSpring;
    material_.normalStiffness =
        inputChecks::getPositive(dict, "normalStiffness");
    material_.tangentialStiffness =
        getInRange(dict, "tangentialStiffness", 0, 0);
    material_.normalDamping = getInRange(dict, "normalDamping", 0, 0);
    material_.tangentialDamping = getInRange(dict, "tangentialDamping", 0, 0);
    material_.friction = getInRange(dict, "friction", 0, 0);
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "bondCreep.H"
#include "demCloud.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(bondCreep, 0);
    addToRunTimeSelectionTable(functionObject, bondCreep, dictionary);
}
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::wordList Foam::functionObjects::bondCreep::columns
(
    const demCloud&
) const
{
    return
    {
        "bondsIntact", "normal", "shear", "twist", "bend",
        "meanNormal", "meanShear", "meanTwist", "meanBend"
    };
}


void Foam::functionObjects::bondCreep::writeRow
(
    Ostream& os,
    const demCloud& cloud
)
{
    const dem::BondCounts bonds = cloud.system().bondCounts();
    const scalar intact = bonds.intact;
    os  << tab << label(bonds.intact);
    for (int m = 0; m < 4; ++m)
    {
        os  << tab << bonds.intactCreep[m] + bonds.brokenCreep[m];
    }
    for (int m = 0; m < 4; ++m)
    {
        os  << tab << (intact > 0 ? bonds.intactCreep[m]/intact : 0);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::bondCreep::bondCreep
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    demTable
    (
        name,
        runTime,
        dict,
        "creep",
        "Bond creep per mechanism (doc/CASE-FORMAT.md, function objects): "
        "sums over every bond since the start [m, m, rad, rad], "
        "then means over the intact bonds"
    )
{}


// ************************************************************************* //

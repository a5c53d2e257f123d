/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "horizontalProfiles.H"
#include "inputChecks.H"
#include "demCloud.H"
#include "volFields.H"
#include "fvcGrad.H"
#include "OFstream.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(horizontalProfiles, 0);
    addToRunTimeSelectionTable(functionObject, horizontalProfiles, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalarField Foam::functionObjects::horizontalProfiles::layerMean
(
    const word& fieldName
) const
{
    const meshGrid& grid = mesh_.lookupObject<demCloud>("demCloud").grid();
    const dem::UniformGrid& g = grid.grid();
    scalarField mean(g.n[2], Zero);

    if (!mesh_.foundObject<volScalarField>(fieldName))
    {
        return mean;
    }
    const scalarField& f =
        mesh_.lookupObject<volScalarField>(fieldName).primitiveField();

    for (label gi = 0; gi < grid.size(); ++gi)
    {
        if (grid.cellOf(gi) >= 0)
        {
            mean[grid.layerOf(gi)] += f[grid.cellOf(gi)];
        }
    }
    // Decomposed: each rank's cells, summed over the ranks
    reduce(mean, sumOp<scalarField>());
    return mean/scalar(g.n[0]*g.n[1]);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::horizontalProfiles::horizontalProfiles
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict)
{
    // No entries of its own
    inputChecks::checkKnownEntries
    (
        dict,
        inputChecks::functionObjectEntryNames()
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::horizontalProfiles::execute()
{
    return true;
}


bool Foam::functionObjects::horizontalProfiles::write()
{
    const demCloud& cloud = mesh_.lookupObject<demCloud>("demCloud");
    const meshGrid& grid = cloud.grid();
    const dem::UniformGrid& g = grid.grid();
    const label nz = g.n[2];
    const scalar dz = g.spacing[2];

    const scalarField p(layerMean("p"));
    const scalarField phi(layerMean("porosity"));
    const scalarField k(layerMean("k"));

    scalarField Usx(nz, Zero), forceZ(nz, Zero);
    const bool wet = mesh_.foundObject<volScalarField>("p");
    const bool haveUs = mesh_.foundObject<volVectorField>("Us");
    tmp<volVectorField> tgradp;
    if (wet)
    {
        tgradp = fvc::grad(mesh_.lookupObject<volScalarField>("p"));
    }
    for (label gi = 0; gi < grid.size(); ++gi)
    {
        const label c = grid.cellOf(gi);
        if (c < 0)
        {
            continue;
        }
        const label layer = grid.layerOf(gi);
        if (haveUs)
        {
            Usx[layer] += mesh_.lookupObject<volVectorField>("Us")[c].x();
        }
        if (wet && mesh_.foundObject<volScalarField>("porosity"))
        {
            const scalar phiC =
                mesh_.lookupObject<volScalarField>("porosity")[c];
            forceZ[layer] -= (1 - phiC)*tgradp()[c].z();
        }
    }
    reduce(Usx, sumOp<scalarField>());
    reduce(forceZ, sumOp<scalarField>());
    Usx /= scalar(g.n[0]*g.n[1]);
    forceZ /= scalar(g.n[0]*g.n[1]);

    // Grain x-displacement binned by the grains' current heights
    const dem::GrainData grains = cloud.grains();
    scalarField shift(nz, Zero);
    labelField count(nz, Zero);
    for (size_t i = 0; i < grains.radius.size(); ++i)
    {
        const label layer = label((grains.position[3*i + 2] - g.origin[2])/dz);
        if (layer >= 0 && layer < nz)
        {
            shift[layer] += grains.displacement[3*i];
            ++count[layer];
        }
    }

    reduce(shift, sumOp<scalarField>());
    reduce(count, sumOp<labelField>());
    if (!Pstream::master())
    {
        return true;
    }

    const fileName dir
    (
        time_.globalPath()/functionObject::outputPrefix/name()/time_.timeName()
    );
    mkDir(dir);
    OFstream os(dir/"profiles.dat");
    os  << "# Horizontally averaged profiles at t = " << time_.timeName()
        << " s (columns: see horizontalProfiles.H)" << nl
        << "# z p porosity k Usx fluidForceZ fluidStressZ grainDisplacementX"
        << nl;

    scalarField stress(nz, Zero);
    scalar above = 0;
    for (label layer = nz - 1; layer >= 0; --layer)
    {
        above += forceZ[layer]*dz;
        stress[layer] = above;
    }
    for (label layer = 0; layer < nz; ++layer)
    {
        os  << g.origin[2] + (layer + 0.5)*dz << ' ' << p[layer] << ' '
            << phi[layer] << ' ' << k[layer] << ' ' << Usx[layer] << ' '
            << forceZ[layer] << ' ' << stress[layer] << ' '
            << (count[layer] ? shift[layer]/count[layer] : 0) << nl;
    }

    return true;
}


// ************************************************************************* //

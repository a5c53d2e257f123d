/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "meshGrid.H"
#include "cyclicPolyPatch.H"
#include "boundBox.H"
#include "volFields.H"
#include "Switch.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::meshGrid::cyclicSides
(
    const fvMesh& mesh,
    const direction dir
) const
{
    label nCyclic = 0;
    label nOther = 0;
    word otherPatch;

    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        const vectorField& n = pp.faceNormals();
        forAll(n, facei)
        {
            if (mag(n[facei][dir]) > 0.5)
            {
                if (isA<cyclicPolyPatch>(pp))
                {
                    ++nCyclic;
                }
                else
                {
                    ++nOther;
                    otherPatch = pp.name();
                }
            }
        }
    }

    if (nCyclic && nOther)
    {
        FatalErrorInFunction
            << "Mesh sides normal to " << vector::componentNames[dir]
            << " mix cyclic and non-cyclic patches (e.g. " << otherPatch
            << "); the grain-to-mesh mapping needs them all cyclic or all"
            << " walls" << nl << exit(FatalError);
    }

    return nCyclic > 0;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshGrid::meshGrid(const fvMesh& mesh)
{
    if (Pstream::parRun())
    {
        FatalErrorInFunction
            << "The grain-to-mesh mapping runs on a serial (undecomposed) mesh"
            << " only for now; run without -parallel" << nl
            << exit(FatalError);
    }

    const boundBox& bb = mesh.bounds();
    const pointField& points = mesh.points();
    const cellList& cells = mesh.cells();
    const faceList& faces = mesh.faces();

    // Cell size from the first cell; every other cell must match it
    const boundBox cell0(cells[0].points(faces, points), false);
    const vector delta = cell0.span();

    for (direction d = 0; d < 3; ++d)
    {
        grid_.origin[d] = bb.min()[d];
        grid_.spacing[d] = delta[d];
        grid_.n[d] = label(std::round(bb.span()[d]/delta[d]));
    }

    const label nExpected = grid_.n[0]*grid_.n[1]*grid_.n[2];
    const scalar tol = 1e-6;

    auto refuse = [&](const label celli, const string& why)
    {
        FatalErrorInFunction
            << "Mesh " << mesh.polyMesh::instance()/polyMesh::meshSubDir
            << " is not a uniform Cartesian mesh (" << why << " at cell "
            << celli << ", centre " << mesh.C()[celli] << ")." << nl
            << "The grain-to-mesh mapping (doc/EQUATIONS.md 6) needs one blockMesh"
            << " hex block with uniform grading: axis-aligned cells of one"
            << " size (any dx, dy, dz)." << nl << exit(FatalError);
    };

    if (mesh.nCells() != nExpected)
    {
        refuse(0, "cell count " + Foam::name(mesh.nCells()) + " differs from "
            + Foam::name(nExpected) + " boxes of the first cell's size");
    }

    cellOfGrid_.setSize(nExpected, -1);
    const scalar boxVolume = delta.x()*delta.y()*delta.z();

    forAll(cells, celli)
    {
        const boundBox cb(cells[celli].points(faces, points), false);

        if (mag(cb.span() - delta) > tol*mag(delta))
        {
            refuse(celli, "cell size " + Foam::name(cb.span()));
        }
        if (mag(mesh.V()[celli] - boxVolume) > tol*boxVolume)
        {
            refuse(celli, "cell is not an axis-aligned box");
        }

        label ijk[3];
        for (direction d = 0; d < 3; ++d)
        {
            const scalar s = (cb.min()[d] - bb.min()[d])/delta[d];
            ijk[d] = label(std::round(s));
            if (mag(s - ijk[d]) > tol)
            {
                refuse(celli, "cell off the lattice");
            }
        }

        const label gi = ijk[0] + grid_.n[0]*(ijk[1] + grid_.n[1]*ijk[2]);
        if (cellOfGrid_[gi] != -1)
        {
            refuse(celli, "two cells on one lattice site");
        }
        cellOfGrid_[gi] = celli;
    }

    // Periodic only where asked: cyclic sides make the DEM box periodic,
    // wall sides close it (the grains' walls stand there, demWalls)
    for (direction d = 0; d < 2; ++d)
    {
        grid_.periodic[d] = cyclicSides(mesh, d);
    }
    if (cyclicSides(mesh, 2))
    {
        FatalErrorInFunction
            << "The mesh's top and bottom must not be cyclic: grains are"
            << " bounded by walls in z" << nl << exit(FatalError);
    }
    grid_.periodic[2] = false;

    Info<< "Uniform grid for the grains: " << grid_.n[0] << " x "
        << grid_.n[1] << " x " << grid_.n[2] << " cells of " << delta
        << " m from " << bb.min() << ", periodic in x: "
        << Switch(grid_.periodic[0]) << ", y: " << Switch(grid_.periodic[1])
        << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshGrid::toMesh(const std::vector<double>& g, scalarField& f) const
{
    forAll(cellOfGrid_, gi)
    {
        f[cellOfGrid_[gi]] = g[gi];
    }
}


void Foam::meshGrid::toMesh(const std::vector<double>& g, vectorField& f) const
{
    forAll(cellOfGrid_, gi)
    {
        f[cellOfGrid_[gi]] = vector(g[3*gi], g[3*gi + 1], g[3*gi + 2]);
    }
}


void Foam::meshGrid::toGrid(const vectorField& f, std::vector<double>& g) const
{
    g.resize(3*cellOfGrid_.size());
    forAll(cellOfGrid_, gi)
    {
        const vector& v = f[cellOfGrid_[gi]];
        g[3*gi] = v.x();
        g[3*gi + 1] = v.y();
        g[3*gi + 2] = v.z();
    }
}


void Foam::meshGrid::toGrid(const scalarField& f, std::vector<double>& g) const
{
    g.resize(cellOfGrid_.size());
    forAll(cellOfGrid_, gi)
    {
        g[gi] = f[cellOfGrid_[gi]];
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "meshGrid.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "Pstream.H"
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
        // Decomposed: faces between ranks are no side of the box, unless a
        // cyclic runs across the cut (processorCyclic)
        const bool cyclic =
            isA<cyclicPolyPatch>(pp) || isA<processorCyclicPolyPatch>(pp);
        if (!cyclic && isA<processorPolyPatch>(pp))
        {
            continue;
        }
        const vectorField& n = pp.faceNormals();
        forAll(n, facei)
        {
            if (mag(n[facei][dir]) > 0.5)
            {
                if (cyclic)
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

    reduce(nCyclic, sumOp<label>());
    const label nOtherHere = nOther;
    reduce(nOther, sumOp<label>());
    if (nOtherHere == 0)
    {
        otherPatch = "on another rank";
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
:
    rankBoxes_{{1, 1}}
{
    // The whole mesh's bounds (boundBox reduces over the ranks)
    const boundBox bb(mesh.points(), true);
    const pointField& points = mesh.points();
    const cellList& cells = mesh.cells();
    const faceList& faces = mesh.faces();

    if (mesh.nCells() == 0)
    {
        FatalErrorInFunction
            << "Rank " << Pstream::myProcNo() << " holds no cells of the"
            << " mesh: decompose it into fewer parts" << nl
            << exit(FatalError);
    }

    // Cell size from the first cell; every other cell, on every rank, must
    // match it
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
            << celli;
        if (Pstream::parRun())
        {
            FatalError<< " of rank " << Pstream::myProcNo();
        }
        FatalError
            << ", centre " << mesh.C()[celli] << ")." << nl
            << "The grain-to-mesh mapping (doc/EQUATIONS.md 6) needs one blockMesh"
            << " hex block with uniform grading: axis-aligned cells of one"
            << " size (any dx, dy, dz)." << nl << exit(FatalError);
    };

    const label nCells = returnReduce(mesh.nCells(), sumOp<label>());
    if (nCells != nExpected)
    {
        refuse(0, "cell count " + Foam::name(nCells) + " differs from "
            + Foam::name(nExpected) + " boxes of the first cell's size");
    }

    cellOfGrid_.setSize(nExpected, -1);
    const scalar boxVolume = delta.x()*delta.y()*delta.z();

    // This rank's block of lattice indices
    labelList lo(3, labelMax), hi(3, labelMin);

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
            lo[d] = min(lo[d], ijk[d]);
            hi[d] = max(hi[d], ijk[d] + 1);
        }

        const label gi = ijk[0] + grid_.n[0]*(ijk[1] + grid_.n[1]*ijk[2]);
        if (cellOfGrid_[gi] != -1)
        {
            refuse(celli, "two cells on one lattice site");
        }
        cellOfGrid_[gi] = celli;
    }

    if (Pstream::parRun())
    {
        findRankBoxes(mesh, lo, hi);
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

void Foam::meshGrid::findRankBoxes
(
    const fvMesh& mesh,
    const labelList& lo,
    const labelList& hi
)
{
    // Each rank's block: its cells must fill it, span the mesh's height, and
    // the blocks must form a regular NX x NY grid of equal boxes numbered x
    // fastest: the DEM library's boxes (dem::Decomposition)
    const label nRanks = Pstream::nProcs();
    const label me = Pstream::myProcNo();
    List<labelList> blocks(nRanks);
    blocks[me] = labelList({lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]});
    Pstream::gatherList(blocks);
    Pstream::scatterList(blocks);

    label nx = 0, ny = 0;
    for (const labelList& b : blocks)
    {
        if (b[2] == 0)
        {
            ++nx;
        }
        if (b[0] == 0)
        {
            ++ny;
        }
    }

    string why;
    if (nx*ny != nRanks || grid_.n[0] % max(nx, 1) || grid_.n[1] % max(ny, 1))
    {
        why = "the parts are not an NX x NY grid of equal boxes";
    }
    else
    {
        const label wx = grid_.n[0]/nx, wy = grid_.n[1]/ny;
        forAll(blocks, r)
        {
            const labelList& b = blocks[r];
            const label ix = r % nx, iy = r/nx;
            const bool regular =
                b[0] == ix*wx && b[1] == (ix + 1)*wx
             && b[2] == iy*wy && b[3] == (iy + 1)*wy
             && b[4] == 0 && b[5] == grid_.n[2];
            if (!regular)
            {
                why = "part " + Foam::name(r) + " holds cells x "
                    + Foam::name(b[0]) + ".." + Foam::name(b[1] - 1) + ", y "
                    + Foam::name(b[2]) + ".." + Foam::name(b[3] - 1) + ", z "
                    + Foam::name(b[4]) + ".." + Foam::name(b[5] - 1)
                    + ", not box (" + Foam::name(ix) + ", " + Foam::name(iy)
                    + ") of " + Foam::name(nx) + " x " + Foam::name(ny)
                    + " over the whole height";
                break;
            }
        }
        const label filled =
            (hi[0] - lo[0])*(hi[1] - lo[1])*(hi[2] - lo[2]);
        if (why.empty() && filled != mesh.nCells())
        {
            why = "part " + Foam::name(me) + " is not a box of cells";
        }
    }
    if (returnReduce(label(why.size()), maxOp<label>()) > 0)
    {
        if (why.empty())
        {
            why = "see the other ranks' messages";
        }
        FatalErrorInFunction
            << "The mesh decomposition (system/decomposeParDict) cannot be"
            << " followed by the grains: " << why.c_str() << "." << nl
            << "The grains are split into NX x NY equal boxes over x and y,"
            << " each holding its rank's whole columns of cells. Decompose"
            << " with method simple (or hierarchical, order xyz) and"
            << " n (NX NY 1), where NX divides the " << grid_.n[0]
            << " cells in x and NY the " << grid_.n[1] << " in y" << nl
            << exit(FatalError);
    }
    rankBoxes_ = {{int(nx), int(nRanks/nx)}};
    Info<< "Grains split over " << nRanks << " ranks as the mesh: "
        << rankBoxes_[0] << " x " << rankBoxes_[1] << " boxes of "
        << grid_.n[0]/rankBoxes_[0] << " x " << grid_.n[1]/rankBoxes_[1]
        << " x " << grid_.n[2] << " cells" << endl;
}


void Foam::meshGrid::followBox(const std::array<double, 2>& upper)
{
    for (int d = 0; d < 2; ++d)
    {
        grid_.spacing[d] = (upper[d] - grid_.origin[d])/grid_.n[d];
    }
}


void Foam::meshGrid::toMesh(const std::vector<double>& g, scalarField& f) const
{
    forAll(cellOfGrid_, gi)
    {
        if (cellOfGrid_[gi] >= 0)
        {
            f[cellOfGrid_[gi]] = g[gi];
        }
    }
}


void Foam::meshGrid::toMesh(const std::vector<double>& g, vectorField& f) const
{
    forAll(cellOfGrid_, gi)
    {
        if (cellOfGrid_[gi] >= 0)
        {
            f[cellOfGrid_[gi]] = vector(g[3*gi], g[3*gi + 1], g[3*gi + 2]);
        }
    }
}


void Foam::meshGrid::sumOverRanks(std::vector<double>& g) const
{
    if (!Pstream::parRun())
    {
        return;
    }
    // Every cell is on one rank and zero on the others
    scalarField all(g.size());
    std::copy(g.begin(), g.end(), all.begin());
    reduce(all, sumOp<scalarField>());
    std::copy(all.begin(), all.end(), g.begin());
}


void Foam::meshGrid::toGrid(const vectorField& f, std::vector<double>& g) const
{
    g.assign(3*cellOfGrid_.size(), 0.0);
    forAll(cellOfGrid_, gi)
    {
        if (cellOfGrid_[gi] >= 0)
        {
            const vector& v = f[cellOfGrid_[gi]];
            g[3*gi] = v.x();
            g[3*gi + 1] = v.y();
            g[3*gi + 2] = v.z();
        }
    }
    sumOverRanks(g);
}


void Foam::meshGrid::toGrid(const scalarField& f, std::vector<double>& g) const
{
    g.assign(cellOfGrid_.size(), 0.0);
    forAll(cellOfGrid_, gi)
    {
        if (cellOfGrid_[gi] >= 0)
        {
            g[gi] = f[cellOfGrid_[gi]];
        }
    }
    sumOverRanks(g);
}


// ************************************************************************* //

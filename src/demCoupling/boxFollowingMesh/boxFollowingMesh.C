/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "boxFollowingMesh.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::boxFollowingMesh::boxFollowingMesh(fvMesh& mesh, const demCloud& cloud)
:
    mesh_(mesh),
    cloud_(cloud),
    points0_(cloud.deformingBox() ? mesh.points() : pointField()),
    length0_(Zero)
{
    const dem::UniformGrid& g = cloud_.grid().grid();
    for (direction d = 0; d < 3; ++d)
    {
        length0_[d] = g.n[d]*g.spacing[d];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::boxFollowingMesh::update()
{
    if (!cloud_.deformingBox())
    {
        return;
    }
    const dem::UniformGrid& g = cloud_.grid().grid();
    pointField points(points0_);
    for (direction d = 0; d < 2; ++d)
    {
        const scalar scale = g.n[d]*g.spacing[d]/length0_[d];
        if (scale == 1)
        {
            continue;
        }
        for (point& p : points)
        {
            p[d] = g.origin[d] + (p[d] - g.origin[d])*scale;
        }
    }
    mesh_.movePoints(points);
}


// ************************************************************************* //

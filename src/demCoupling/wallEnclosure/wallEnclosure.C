/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "wallEnclosure.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wallEnclosure::wallEnclosure
(
    const dem::System& dem,
    const dem::UniformGrid& mesh
)
:
    walls_(),
    lid_(-1)
{
    std::array<bool, 3> hasLower{false, false, false};
    std::array<bool, 3> hasUpper{false, false, false};
    for (int w = 0; w < dem.wallCount(); ++w)
    {
        walls_.push_back(dem.wall(w));
        const dem::WallData& wall = walls_.back();
        const int d = wall.spec.axis;
        if (wall.spec.side == dem::WallSpec::Side::lower)
        {
            lower_[d] = hasLower[d] ? max(lower_[d], wall.position) : wall.position;
            hasLower[d] = true;
        }
        else
        {
            upper_[d] = hasUpper[d] ? min(upper_[d], wall.position) : wall.position;
            hasUpper[d] = true;
            if (d == 2 && (lid_ < 0 || wall.position > walls_[lid_].position))
            {
                lid_ = w;
            }
        }
    }

    for (int d = 0; d < 3; ++d)
    {
        if (!hasLower[d])
        {
            lower_[d] = mesh.origin[d];
        }
        if (!hasUpper[d])
        {
            upper_[d] = mesh.origin[d] + mesh.n[d]*mesh.spacing[d];
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::wallEnclosure::area(const label w) const
{
    const int d = walls_[w].spec.axis;
    return length((d + 1) % 3)*length((d + 2) % 3);
}


// ************************************************************************* //

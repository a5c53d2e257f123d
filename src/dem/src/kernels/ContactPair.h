// ContactPair.h
// What a contact law may need to know of the two grains besides the contact's kinematics:
// their radii (the dilation radius of a capsule, not its bounding radius) and inverse masses.
// A wall: radiusJ = radiusI, inverseMassJ = 0.
#pragma once

#include "backends/HostDevice.h"

namespace dem
{
namespace detail
{
inline namespace DEM_KERNEL_NS
{

struct ContactPair
{
    double radiusI, radiusJ, inverseMassI, inverseMassJ;
};

} // namespace DEM_KERNEL_NS
} // namespace detail
} // namespace dem

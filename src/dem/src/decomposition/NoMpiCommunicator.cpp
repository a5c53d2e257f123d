// NoMpiCommunicator.cpp
// A library built without MPI: one process; a decomposition into more boxes is refused.
#include "dem/Mpi.h"
#include "engine/Communicator.h"

#include <string>

namespace dem
{

bool mpiBuild()
{
    return false;
}

MpiSession::MpiSession(int*, char***) {}
MpiSession::~MpiSession() = default;
double MpiSession::sum(double value) const
{
    return value;
}
double MpiSession::max(double value) const
{
    return value;
}
double MpiSession::min(double value) const
{
    return value;
}
void MpiSession::barrier() const {}

namespace detail
{

std::unique_ptr<Communicator> makeWorldCommunicator(int ranks)
{
    throw Error("decomposition into " + std::to_string(ranks) +
                " boxes: this DEM library was built without MPI (install libopenmpi-dev and "
                "rebuild with -DDEM_MPI=ON)");
}

} // namespace detail
} // namespace dem

// Communicator.h
// What the engine needs of MPI, in plain C++ (the engine is also compiled by nvcc, and no MPI
// header reaches it): reductions and the exchange of host buffers between ranks. Implemented
// over MPI_COMM_WORLD in decomposition/MpiCommunicator.cpp; a build without MPI refuses to
// make one.
#pragma once

#include <memory>
#include <vector>

namespace dem
{
namespace detail
{

class Communicator
{
public:
    virtual ~Communicator() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    //- This rank's index among the ranks on its node (MPI_COMM_TYPE_SHARED): its GPU.
    virtual int localRank() const = 0;
    virtual double sum(double value) const = 0;
    virtual double max(double value) const = 0;
    //- values[0..count) replaced by their sums over all ranks (host memory).
    virtual void sumInPlace(double* values, long count) const = 0;
    //- Sum of value over the ranks below this one.
    virtual long long exclusiveSum(long long value) const = 0;
    //- send[r] goes to rank r (send.size() == size()); returns what each rank sent here. With
    //- receiveSizes (one per rank, known to both sides), only the ranks with something to
    //- send or receive take part and the sizes are not exchanged first.
    virtual std::vector<std::vector<double>>
    exchange(const std::vector<std::vector<double>>& send,
             const std::vector<long>* receiveSizes = nullptr) const = 0;
};

//- A communicator over MPI_COMM_WORLD; throws dem::Error naming what is missing when the
//- library was built without MPI or MPI is not running, or its size is not `ranks`.
std::unique_ptr<Communicator> makeWorldCommunicator(int ranks);

} // namespace detail
} // namespace dem

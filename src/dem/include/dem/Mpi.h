// dem/Mpi.h
// MPI for programs that run a decomposed dem::System (Parameters::decomposition) without
// including mpi.h themselves: MpiSession starts and ends MPI, the sums and maxima below reduce
// over MPI_COMM_WORLD. A library built without MPI (DEM_MPI off, or no MPI found) runs one
// process: the session is then rank 0 of 1 and a decomposition of more than one box is refused.
#pragma once

#include "dem/Error.h"

namespace dem
{

//- true when the library was built with MPI.
DEM_API bool mpiBuild();

//- Starts MPI (MPI_Init_thread, funneled) unless it is running, ends it when it started it.
class DEM_API MpiSession
{
public:
    MpiSession(int* argc, char*** argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    int rank() const { return rank_; }
    int size() const { return size_; }
    //- Sum / maximum / minimum of value over all ranks (each rank gets the result).
    double sum(double value) const;
    double max(double value) const;
    double min(double value) const;
    void barrier() const;

private:
    int rank_ = 0, size_ = 1;
    bool started_ = false;
};

} // namespace dem

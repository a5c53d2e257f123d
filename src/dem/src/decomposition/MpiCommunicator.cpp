// MpiCommunicator.cpp
// The engine's Communicator and the public MpiSession over MPI_COMM_WORLD (built with MPI).
#include "dem/Mpi.h"
#include "engine/Communicator.h"

#include <mpi.h>

#include <algorithm>
#include <string>

namespace dem
{

bool mpiBuild()
{
    return true;
}

MpiSession::MpiSession(int* argc, char*** argv)
{
    int running = 0;
    MPI_Initialized(&running);
    if (!running)
    {
        int provided = 0;
        MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
        started_ = true;
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession()
{
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (started_ && !finalized)
        MPI_Finalize();
}

namespace
{
double reduce(double value, MPI_Op op)
{
    double out = 0.0;
    MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, op, MPI_COMM_WORLD);
    return out;
}
} // namespace

double MpiSession::sum(double value) const
{
    return reduce(value, MPI_SUM);
}
double MpiSession::max(double value) const
{
    return reduce(value, MPI_MAX);
}
double MpiSession::min(double value) const
{
    return reduce(value, MPI_MIN);
}
void MpiSession::barrier() const
{
    MPI_Barrier(MPI_COMM_WORLD);
}

namespace detail
{

namespace
{

class WorldCommunicator final : public Communicator
{
public:
    WorldCommunicator()
    {
        MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
        MPI_Comm_size(MPI_COMM_WORLD, &size_);
    }
    int rank() const override { return rank_; }
    int size() const override { return size_; }
    int localRank() const override
    {
        MPI_Comm node;
        MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
        int local = 0;
        MPI_Comm_rank(node, &local);
        MPI_Comm_free(&node);
        return local;
    }
    double sum(double value) const override { return reduce(value, MPI_SUM); }
    double max(double value) const override { return reduce(value, MPI_MAX); }
    void sumInPlace(double* values, long count) const override
    {
        // In slices: MPI counts are int
        const long slice = 1L << 28;
        for (long first = 0; first < count; first += slice)
            MPI_Allreduce(MPI_IN_PLACE, values + first, int(std::min(slice, count - first)),
                          MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    }
    long long exclusiveSum(long long value) const override
    {
        long long out = 0;
        MPI_Exscan(&value, &out, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
        return rank_ == 0 ? 0 : out; // MPI leaves rank 0's result undefined
    }

    std::vector<std::vector<double>> exchange(const std::vector<std::vector<double>>& send,
                                              const std::vector<long>* receiveSizes) const override
    {
        if (int(send.size()) != size_)
            throw Error("internal error: exchange needs one buffer per rank");
        std::vector<long> sizes(static_cast<std::size_t>(size_), 0);
        if (receiveSizes)
            sizes = *receiveSizes;
        else
        {
            std::vector<long> sent(static_cast<std::size_t>(size_));
            for (int r = 0; r < size_; ++r)
                sent[r] = long(send[r].size());
            MPI_Alltoall(sent.data(), 1, MPI_LONG, sizes.data(), 1, MPI_LONG, MPI_COMM_WORLD);
        }
        std::vector<std::vector<double>> received(static_cast<std::size_t>(size_));
        std::vector<MPI_Request> requests;
        requests.reserve(2 * std::size_t(size_));
        for (int r = 0; r < size_; ++r)
        {
            received[r].resize(std::size_t(sizes[r]));
            if (sizes[r] == 0)
                continue;
            if (sizes[r] > 2147483647L)
                throw Error("exchange of " + std::to_string(sizes[r]) +
                            " values in one message: more than MPI's int count allows");
            requests.emplace_back();
            MPI_Irecv(received[r].data(), int(sizes[r]), MPI_DOUBLE, r, kTag, MPI_COMM_WORLD,
                      &requests.back());
        }
        for (int r = 0; r < size_; ++r)
        {
            if (send[r].empty())
                continue;
            requests.emplace_back();
            MPI_Isend(send[r].data(), int(send[r].size()), MPI_DOUBLE, r, kTag, MPI_COMM_WORLD,
                      &requests.back());
        }
        MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
        return received;
    }

private:
    static constexpr int kTag = 27;
    int rank_ = 0, size_ = 1;
};

} // namespace

std::unique_ptr<Communicator> makeWorldCommunicator(int ranks)
{
    int running = 0, finalized = 0;
    MPI_Initialized(&running);
    MPI_Finalized(&finalized);
    if (!running || finalized)
        throw Error("decomposition " + std::to_string(ranks) +
                    " boxes: MPI is not running (start it with dem::MpiSession, and the "
                    "program with mpirun -np " +
                    std::to_string(ranks) + ")");
    int size = 0;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (size != ranks)
        throw Error("decomposition into " + std::to_string(ranks) + " boxes needs " +
                    std::to_string(ranks) + " MPI ranks, but mpirun started " +
                    std::to_string(size) + " (mpirun -np " + std::to_string(ranks) + ")");
    return std::make_unique<WorldCommunicator>();
}

} // namespace detail
} // namespace dem

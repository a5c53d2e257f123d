// CudaEngine.cu
// The CUDA backend: the same engine source as CpuEngine.cpp, compiled by nvcc over Thrust's
// CUDA system. Selected at run time when a device answers.
#include "backends/CudaExecution.cuh"
#include "dem/System.h"
#include "engine/EngineImpl.h"

namespace dem
{

int cudaDeviceCount()
{
    int count = 0;
    if (cudaGetDeviceCount(&count) != cudaSuccess)
    {
        cudaGetLastError(); // clear the sticky "no driver" error
        return 0;
    }
    return count;
}

namespace detail
{

std::unique_ptr<Engine> makeCudaEngine(const Parameters& parameters)
{
    int count = 0;
    const cudaError_t status = cudaGetDeviceCount(&count);
    if (status != cudaSuccess || count == 0)
    {
        cudaGetLastError(); // clear the sticky error before the caller falls back
        throw Error(std::string("backend 'cuda' requested but no CUDA device answers (") +
                    (status != cudaSuccess ? cudaGetErrorString(status) : "0 devices") +
                    "); use backend 'cpu' or 'auto'");
    }
    // Over MPI ranks: one device per rank, the ranks of a node taking its devices in turn.
    if (parameters.decomposition.rankCount() > 1)
    {
        const int device =
            makeWorldCommunicator(parameters.decomposition.rankCount())->localRank() % count;
        if (cudaSetDevice(device) != cudaSuccess)
            throw Error("cudaSetDevice(" + std::to_string(device) + ") failed");
    }
    return std::make_unique<EngineImpl<CudaExecution>>(parameters);
}

} // namespace detail
} // namespace dem

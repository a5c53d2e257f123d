// DeviceMemoryCache.cuh
// Device memory for the temporary storage of Thrust's algorithms (reductions, scans, sorts),
// kept between calls so that a step allocates no device memory once the first steps have sized
// the blocks (cudaMalloc/cudaFree synchronise the device and cost far more than a reduction over
// a few thousand grains). The caching is CUB's own CachingDeviceAllocator; this class only gives
// it the allocator interface of thrust::cuda::par(cache). Owned by the engine's CudaExecution,
// freed with it. Compiled by nvcc only.
#pragma once

#include "backends/CudaCheck.cuh"

#include <cub/util_allocator.cuh>

#include <cstddef>

namespace dem
{
namespace detail
{

class DeviceMemoryCache
{
public:
    using value_type = char; // Thrust's allocator interface: blocks of bytes

    DeviceMemoryCache() = default;
    DeviceMemoryCache(const DeviceMemoryCache&) = delete;
    DeviceMemoryCache& operator=(const DeviceMemoryCache&) = delete;

    char* allocate(std::size_t bytes)
    {
        void* p = nullptr;
        DEM_CUDA_CHECK(cache_.DeviceAllocate(&p, bytes));
        return static_cast<char*>(p);
    }

    //- Back to the cache (no throw: Thrust hands blocks back from destructors).
    void deallocate(char* p, std::size_t) { cache_.DeviceFree(p); }

private:
    // Power-of-two bins from 256 B to 1 TiB: every request is cached (CUB's default caches
    // nothing above 2 MB, less than a sort's temporary storage at 1e6 grains), at the price of
    // up to twice the requested size per block.
    cub::CachingDeviceAllocator cache_{2, 8, 40};
};

} // namespace detail
} // namespace dem

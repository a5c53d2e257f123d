// DeviceMemoryCache.cuh
// Device memory for the temporary storage of Thrust's algorithms (reductions, scans, sorts),
// kept between calls: blocks handed back are reused for later requests of the same or a smaller
// size instead of being freed, so a step allocates no device memory once the first steps have
// sized the blocks (cudaMalloc/cudaFree synchronise the device and cost far more than a
// reduction over a few thousand grains). Used as the allocator of thrust::cuda::par(cache),
// owned by the engine's CudaExecution, freed with it. Compiled by nvcc only.
#pragma once

#include "backends/CudaCheck.cuh"

#include <cstddef>
#include <map>

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

    ~DeviceMemoryCache()
    {
        // No throwing from a destructor: a failing cudaFree here means the context is gone.
        for (const auto& block : free_)
            cudaFree(block.second);
        for (const auto& block : inUse_)
            cudaFree(block.first);
    }

    char* allocate(std::size_t bytes)
    {
        // The smallest free block that is large enough (the requests of a run repeat).
        const auto it = free_.lower_bound(bytes);
        char* p = nullptr;
        std::size_t size = bytes;
        if (it != free_.end())
        {
            p = it->second;
            size = it->first;
            free_.erase(it);
        }
        else
        {
            void* raw = nullptr;
            DEM_CUDA_CHECK(cudaMalloc(&raw, bytes));
            p = static_cast<char*>(raw);
        }
        inUse_[p] = size;
        return p;
    }

    void deallocate(char* p, std::size_t)
    {
        const auto it = inUse_.find(p);
        if (it == inUse_.end())
            return; // not ours: nothing to do (Thrust hands back only what it was given)
        free_.emplace(it->second, p);
        inUse_.erase(it);
    }

private:
    std::multimap<std::size_t, char*> free_; // size -> block
    std::map<char*, std::size_t> inUse_;     // block -> size
};

} // namespace detail
} // namespace dem

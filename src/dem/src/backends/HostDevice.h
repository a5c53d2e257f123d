// HostDevice.h
// Markers that let one kernel source compile with g++ (OpenMP backend) and nvcc (CUDA backend).
// DEM_KERNEL_NS gives every kernel type a backend-specific inline namespace, so the two
// compilations of the same header never define one symbol twice (one-definition rule).
#pragma once

#if defined(__CUDACC__)
#define DEM_HD __host__ __device__ __forceinline__
#define DEM_KERNEL_NS cudaKernels
#else
#define DEM_HD inline __attribute__((always_inline))
#define DEM_KERNEL_NS cpuKernels
#endif

#include <Eigen/Core>
#include <Eigen/Geometry> // cross()

namespace dem
{
namespace detail
{

using Eigen::Quaterniond;
using Eigen::Vector3d;

//- Add into memory that several threads may hit at once (deposit on CUDA).
DEM_HD void atomicAddDouble(double* address, double value)
{
#if defined(__CUDA_ARCH__)
    atomicAdd(address, value);
#else
    *address += value; // CPU scatter kernels run serially: deterministic sums
#endif
}

//- Store value where several threads may store the same value at once (a relaxed atomic
//- store; nothing reads it before the pass ends).
DEM_HD void storeShared(int* address, int value)
{
#if defined(__CUDA_ARCH__)
    *static_cast<volatile int*>(address) = value;
#else
    __atomic_store_n(address, value, __ATOMIC_RELAXED);
#endif
}

//- Ask for the cache line at address ahead of its use (CPU: a prefetch; GPU: nothing).
DEM_HD void prefetch(const void* address)
{
#if defined(__CUDA_ARCH__)
    (void)address;
#else
    __builtin_prefetch(address);
#endif
}

} // namespace detail
} // namespace dem

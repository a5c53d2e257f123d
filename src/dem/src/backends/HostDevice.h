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

//- Four doubles added and scaled as one value, where a sum of 3-vectors runs in a loop that
//- GCC does not vectorise by itself (Eigen's 3-vectors compile to scalar code): one 256-bit
//- register on the CPU (GCC vector extensions), four doubles on the GPU. Lane by lane the
//- same IEEE operations as on the 3-vectors, so the sums keep every bit; the fourth lane is
//- scratch. Built as Packed4d{a, b, c, d}: from four adjacent loads, one vector load.
#if defined(__CUDACC__)
struct Packed4d
{
    double lane[4];
    DEM_HD double operator[](int k) const { return lane[k]; }
    DEM_HD Packed4d& operator+=(const Packed4d& b)
    {
        for (int k = 0; k < 4; ++k)
            lane[k] += b.lane[k];
        return *this;
    }
};
DEM_HD Packed4d operator*(double s, const Packed4d& a)
{
    return Packed4d{s * a.lane[0], s * a.lane[1], s * a.lane[2], s * a.lane[3]};
}
#else
typedef double Packed4d __attribute__((vector_size(32)));
#endif

//- The first three lanes of a Packed4d.
DEM_HD Vector3d firstThree(const Packed4d& a)
{
    return Vector3d(a[0], a[1], a[2]);
}

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

// CudaExecution.cuh
// CUDA backend of the kernels: Thrust's CUDA system for storage, sorting and scans, one thread
// per grain (or cell) for the kernels. Compiled by nvcc only.
#pragma once

#include "dem/Error.h"

#include <thrust/iterator/counting_iterator.h>
#include <thrust/reduce.h>
#include <thrust/system/cuda/execution_policy.h>
#include <thrust/system/cuda/vector.h>

#include <cuda_runtime.h>

#include <string>

namespace dem
{
namespace detail
{

template <class F>
__global__ void forEachKernel(F f, int n)
{
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n)
        f(i);
}

template <class F>
__global__ void forEachPairKernel(F f, long n)
{
    const long i = long(blockIdx.x) * blockDim.x + threadIdx.x;
    if (i < n)
        f(i);
}

template <class F>
__global__ void forEachStoreKernel(F f, int n, double* out)
{
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n)
        out[i] = f(i);
}

inline void checkCuda(cudaError_t status, const char* what)
{
    if (status != cudaSuccess)
        throw Error(std::string("CUDA error in ") + what + ": " + cudaGetErrorString(status));
}

struct MaxOfDoubles
{
    __host__ __device__ double operator()(double a, double b) const { return a > b ? a : b; }
};

struct CudaExecution
{
    template <class T>
    using Vector = thrust::cuda::vector<T>;

    static auto policy() { return thrust::cuda::par; }
    //- Per-pair vectors stored pair by pair (see PairView).
    static constexpr bool kPairMajor = false;
    static const char* name() { return "cuda"; }
    static int threads() { return 1; }
    static constexpr int kBlock = 128;

    template <class F>
    static void forEach(int n, const F& f)
    {
        if (n <= 0)
            return;
        forEachKernel<<<(n + kBlock - 1) / kBlock, kBlock>>>(f, n);
        checkCuda(cudaGetLastError(), "kernel launch");
    }

    template <class F>
    static void forEachPair(long n, const F& f)
    {
        if (n <= 0)
            return;
        forEachPairKernel<<<int((n + kBlock - 1) / kBlock), kBlock>>>(f, n);
        checkCuda(cudaGetLastError(), "kernel launch");
    }

    template <class F>
    static void forEachScatter(int n, const F& f)
    {
        forEach(n, f); // atomics in the kernel
    }

    template <class F>
    static double maxOf(int n, const F& f)
    {
        if (n <= 0)
            return 0.0;
        const Vector<double> values = valuesOf(n, f);
        return thrust::reduce(policy(), values.begin(), values.end(), 0.0, MaxOfDoubles());
    }

    template <class F>
    static double sumOf(int n, const F& f)
    {
        if (n <= 0)
            return 0.0;
        const Vector<double> values = valuesOf(n, f);
        return thrust::reduce(policy(), values.begin(), values.end(), 0.0);
    }

private:
    //- f(0), ..., f(n-1) on the device (each evaluated once: f may have side effects).
    template <class F>
    static Vector<double> valuesOf(int n, const F& f)
    {
        Vector<double> values(n);
        forEachStoreKernel<<<(n + kBlock - 1) / kBlock, kBlock>>>(
            f, n, thrust::raw_pointer_cast(values.data()));
        checkCuda(cudaGetLastError(), "kernel launch");
        return values;
    }
};

} // namespace detail
} // namespace dem

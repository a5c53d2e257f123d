// CudaExecution.cuh
// CUDA backend of the kernels: Thrust's CUDA system for storage, sorting and scans, one thread
// per grain (or cell) for the kernels. Compiled by nvcc only.
//
// An engine owns one CudaExecution (EngineImpl::exec_): its Thrust policy draws every temporary
// buffer from a DeviceMemoryCache, and the reductions that end each step write into a scratch
// vector that only grows, so a step allocates no device memory after the first ones. Every
// launch and runtime call is checked (CudaCheck.cuh); the reductions, which end every step and
// synchronise, turn a fault of the step's kernels into a dem::Error.
#pragma once

#include "backends/CudaCheck.cuh"
#include "backends/DeviceMemoryCache.cuh"
#include "dem/State.h"

#include <thrust/reduce.h>
#include <thrust/system/cuda/execution_policy.h>
#include <thrust/system/cuda/vector.h>

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

//- One thread per pair (OmpExecution::forEachTouchingPair): a pair that cannot touch only
//- clears its history and points at the zero record (its lane idles while the others of the
//- warp compute); one that may touch gets its own record, p + 1.
template <class K>
__global__ void forEachTouchingPairKernel(K kernel, long n)
{
    int* slot = kernel.pairs.contactSlot;
    const long p = long(blockIdx.x) * blockDim.x + threadIdx.x;
    if (p >= n)
        return;
    const bool touch = kernel.mayTouch(p);
    kernel.keepHistoryIf(touch, p);
    slot[p] = touch ? int(p) + 1 : 0;
    if (touch)
    {
        kernel.pairs.markMayTouch(kernel.pairs.owner[p], kernel.pairs.partner[p]);
        kernel(p);
    }
}

template <class F>
__global__ void forEachStoreKernel(F f, int n, double* out)
{
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n)
        out[i] = f(i);
}

struct MaxOfDoubles
{
    __host__ __device__ double operator()(double a, double b) const { return a > b ? a : b; }
};

class CudaExecution
{
public:
    template <class T>
    using Vector = thrust::cuda::vector<T>;

    explicit CudaExecution(int /*threads: the CPU's*/) {}
    CudaExecution(const CudaExecution&) = delete;
    CudaExecution& operator=(const CudaExecution&) = delete;

    //- Thrust's CUDA policy with this engine's cached temporary storage (synchronous, like
    //- thrust::cuda::par).
    auto policy() { return thrust::cuda::par(cache_); }
    //- Per-pair vectors stored pair by pair (see PairView).
    static constexpr bool kPairMajor = false;
    static const char* name() { return "cuda"; }
    static int threads() { return 1; }
    //- The CPU's choice of its team size around each step (OmpExecution); nothing here.
    static void stepBegins() {}
    static void stepEnds() {}
    static ThreadUse threadUse() { return ThreadUse{}; }
    static constexpr int kBlock = 128;

    template <class F>
    static void forEach(int n, const F& f)
    {
        if (n <= 0)
            return;
        forEachKernel<<<(n + kBlock - 1) / kBlock, kBlock>>>(f, n);
        DEM_CUDA_CHECK_LAUNCH("forEachKernel");
    }

    //- The pair pass over kernel.pairs (OmpExecution::forEachTouchingPair).
    template <class K>
    static void forEachTouchingPair(const K& kernel)
    {
        const long n = kernel.pairs.count;
        if (n <= 0)
            return;
        forEachTouchingPairKernel<<<int((n + kBlock - 1) / kBlock), kBlock>>>(kernel, n);
        DEM_CUDA_CHECK_LAUNCH("forEachTouchingPairKernel");
    }

    template <class F>
    static void forEachScatter(int n, const F& f)
    {
        forEach(n, f); // atomics in the kernel
    }

    //- max(0, f(0), ..., f(n-1)); f may have side effects (each i runs once).
    template <class F>
    double maxOf(int n, const F& f)
    {
        if (n <= 0)
            return 0.0;
        const double* v = valuesOf(n, f);
        return DEM_THRUST_CHECK(thrust::reduce(policy(), v, v + n, 0.0, MaxOfDoubles()));
    }

    template <class F>
    double sumOf(int n, const F& f)
    {
        if (n <= 0)
            return 0.0;
        const double* v = valuesOf(n, f);
        return DEM_THRUST_CHECK(thrust::reduce(policy(), v, v + n, 0.0));
    }

private:
    //- f(0), ..., f(n-1) into the scratch vector (each evaluated once: f may have side effects).
    template <class F>
    const double* valuesOf(int n, const F& f)
    {
        if (values_.size() < std::size_t(n))
            values_.resize(n); // grows with the grain count, never shrinks
        double* out = thrust::raw_pointer_cast(values_.data());
        forEachStoreKernel<<<(n + kBlock - 1) / kBlock, kBlock>>>(f, n, out);
        DEM_CUDA_CHECK_LAUNCH("forEachStoreKernel");
        return out;
    }

    DeviceMemoryCache cache_;
    Vector<double> values_;
};

} // namespace detail
} // namespace dem

// OmpExecution.h
// CPU backend of the kernels: Thrust's OpenMP system for storage, sorting and scans, plain
// OpenMP loops (static schedule) for the per-grain kernels. Results do not depend on the thread
// count (sums run over fixed blocks), so a restarted run repeats the uninterrupted one bit for
// bit. Stateless: the engine holds an instance (EngineImpl::exec_) only because the CUDA policy
// keeps cached device memory.
#pragma once

#include <thrust/system/omp/execution_policy.h>
#include <thrust/system/omp/vector.h>

#include <omp.h>

#include <algorithm>
#include <vector>

namespace dem
{
namespace detail
{

struct OmpExecution
{
    template <class T>
    using Vector = thrust::omp::vector<T>;

    static auto policy() { return thrust::omp::par; }
    //- Per-pair vectors stored pair by pair (see PairView).
    static constexpr bool kPairMajor = true;
    static const char* name() { return "cpu"; }
    static int threads() { return omp_get_max_threads(); }
    //- Below this many items a kernel runs on one thread: forking costs more than it saves,
    //- and on a loaded machine a descheduled thread would stall every barrier.
    static constexpr int kParallelThreshold = 4096;

    template <class F>
    static void forEach(int n, const F& f)
    {
#pragma omp parallel for schedule(static) if (n >= kParallelThreshold)
        for (int i = 0; i < n; ++i)
            f(i);
    }

    //- Per-pair kernels: straight-line bodies, vectorised across consecutive items. Vector and
    //- scalar (remainder) iterations give the same bits: the CPU build does not contract a*b+c
    //- into fused multiply-adds (-ffp-contract=off), so where a thread's range starts does not
    //- change any result.
    template <class F>
    static void forEachPair(long n, const F& f)
    {
#pragma omp parallel if (n >= kParallelThreshold)
        {
            const F local = f; // members become loop invariants
#pragma omp for simd schedule(static) nowait
            for (long i = 0; i < n; ++i)
                local(i);
        } // the join is the only barrier
    }

    //- Kernels that add into shared cells: serial on the CPU (deterministic, and cheap next to
    //- a fluid step).
    template <class F>
    static void forEachScatter(int n, const F& f)
    {
        for (int i = 0; i < n; ++i)
            f(i);
    }

    //- max(0, f(0), ..., f(n-1)); f may have side effects (each i runs once).
    template <class F>
    static double maxOf(int n, const F& f)
    {
        double result = 0.0;
#pragma omp parallel for schedule(static) reduction(max : result) if (n >= kParallelThreshold)
        for (int i = 0; i < n; ++i)
            result = std::max(result, f(i));
        return result;
    }

    //- Sum of f(i) in an order fixed by n alone: kSumBlocks partial sums over fixed ranges,
    //- added in order, whatever the thread count.
    static constexpr int kSumBlocks = 64;
    template <class F>
    static double sumOf(int n, const F& f)
    {
        double partial[kSumBlocks];
#pragma omp parallel for schedule(static) if (n >= kParallelThreshold)
        for (int b = 0; b < kSumBlocks; ++b)
        {
            const long first = long(n) * b / kSumBlocks, last = long(n) * (b + 1) / kSumBlocks;
            double s = 0.0;
            for (long i = first; i < last; ++i)
                s += f(int(i));
            partial[b] = s;
        }
        double sum = 0.0;
        for (double s : partial)
            sum += s;
        return sum;
    }
};

} // namespace detail
} // namespace dem

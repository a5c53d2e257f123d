// OmpExecution.h
// CPU backend of the kernels: Thrust's OpenMP system for storage, sorting and scans, plain
// OpenMP loops (static schedule) for the per-grain kernels. Results do not depend on the thread
// count (sums run over fixed blocks), so a restarted run repeats the uninterrupted one bit for
// bit. The engine's instance (EngineImpl::exec_) holds the choice of the team size from step
// to step (AdaptiveThreads.h); the kernels' loops are static.
#pragma once

#include "backends/AdaptiveThreads.h"
#include "backends/RecordStaging.h"
#include "dem/State.h"
#include "kernels/Views.h"

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

    //- threads: Parameters::threads (0: OpenMP's default, and the team chosen step by step
    //- between 1 and that; N > 0: N threads, always).
    explicit OmpExecution(int threads)
        : team_(threads > 0 ? threads : omp_get_max_threads(), threads == 0)
    {
        omp_set_num_threads(team_.team());
    }

    static auto policy() { return thrust::omp::par; }
    //- Per-pair vectors stored pair by pair (see PairView).
    static constexpr bool kPairMajor = true;
    static const char* name() { return "cpu"; }
    //- The threads the run may use (the team of a step may be one, AdaptiveThreads).
    int threads() const { return team_.use().most; }
    const ThreadUse& threadUse() const { return team_.use(); }
    //- Around each step: the team for the step (omp_set_num_threads of the calling thread,
    //- which every parallel region and Thrust call of the step then uses; set at every step,
    //- as another System of the process may have set its own), and the step's time for the
    //- choice of the next.
    void stepBegins()
    {
        omp_set_num_threads(team_.team());
        if (team_.use().adaptive)
            stepStart_ = omp_get_wtime();
    }
    void stepEnds() { team_.stepTook(team_.use().adaptive ? omp_get_wtime() - stepStart_ : 0.0); }
    //- Below this many items a kernel runs on one thread: forking costs more than it saves.
    //- 4096 until 6 Dec 2026, when a bed of 1200 grains on two threads of a quiet AMD EPYC
    //- was found 1.8 times as fast with 1024; on a loaded machine, or where a second thread
    //- does not pay, the adaptive team (AdaptiveThreads.h) falls back to one thread.
    static constexpr int kParallelThreshold = 1024;

    template <class F>
    static void forEach(int n, const F& f)
    {
#pragma omp parallel for schedule(static) if (n >= kParallelThreshold)
        for (int i = 0; i < n; ++i)
            f(i);
    }

    //- The pair pass over the pairs of kernel.pairs (a PairForceKernel): those for which
    //- kernel.mayTouch(p) holds are evaluated, the others get a cleared history and the zero
    //- record (contactSlot[p] = 0). Per thread, over its range of pairs in blocks of
    //- kBlockPairs: both grains' positions staged field by field (RecordStaging.h: whole-record
    //- loads and shuffles instead of element loads) and the test vectorised over them; the
    //- pairs that may touch listed in order into a batch, and the k-th pair the thread lists
    //- given record begin + k + 1 (records stay in pair order; each thread's within its own
    //- range). Once the batch holds kBlockPairs pairs or more, or the range ends: the batch's
    //- grains and history copied into a contiguous scratch (scalar); the contact law
    //- vectorised over it kChunk pairs at a time, both grains' position and velocity records
    //- staged field by field first (PairGrainRecords; the loop then loads whole vectors, where
    //- element loads and the extraction of each lane's index were half its instructions);
    //- the history copied back; both grains of each pair marked for GatherKick
    //- (PairView::markMayTouch). Batches rather than blocks: a flowing bed has a
    //- few pairs in a block that may touch, and a vector loop over so few ran at a quarter of
    //- its speed. Each pair's arithmetic is that of a plain loop over all pairs (vector and
    //- scalar iterations round alike, -ffp-contract=off), so neither the thread count nor the
    //- blocks change a bit.
    static constexpr int kBlockPairs = 512;
    template <class K>
    static void forEachTouchingPair(const K& kernel)
    {
        constexpr int kHistory = 3 * kHistoryVectors;
        constexpr int B = kBlockPairs; // staging stride: field f of the k-th pair at f B + k
        constexpr int kBatch = 2 * B;  // a batch of B - 1 pairs and a block of B that may touch
        constexpr int kChunk = 64;     // pairs of a batch staged at a time (in L1), stride kChunk
        const long n = kernel.pairs.count;
#pragma omp parallel if (n >= kParallelThreshold)
        {
            const K local = kernel; // members become loop invariants
            const PairView& pairs = local.pairs;
            const double* positions = local.g.packedPositionRadius;
            const double* velocities = local.g.packedVelocities;
            const long hs = pairs.historyStride();
            int pair[kBatch], owner[kBatch], partner[kBatch];
            double history[kHistory * kBatch];
            alignas(64) double positionI[4 * B], positionJ[4 * B]; // owners', partners'
            alignas(64) double velocityI[8 * kChunk], velocityJ[8 * kChunk];
            const int threads = omp_get_num_threads(), thread = omp_get_thread_num();
            const long begin = n * thread / threads, end = n * (thread + 1) / threads;
            long batchRecord = begin + 1; // the record of the batch's first pair
            int count = 0;                // pairs in the batch
            for (long first = begin; first < end; first += B)
            {
                const int size = int(std::min<long>(B, end - first));
                int* slot = pairs.contactSlot + first;
                staging::stageRecords<4>(positions, pairs.owner + first, size, positionI, B);
                staging::stageRecords<4>(positions, pairs.partner + first, size, positionJ, B);
#pragma omp simd
                for (int k = 0; k < size; ++k)
                {
                    const long p = first + k;
                    const bool touch = local.mayTouch(p, pairs.owner[p], pairs.partner[p],
                                                      positionI + k, positionJ + k, B);
                    local.keepHistoryIf(touch, p);
                    slot[k] = touch;
                }
                for (int k = 0; k < size; ++k)
                {
                    const int touch = slot[k];    // 0 or 1; arithmetic, not a branch
                    pair[count] = int(first) + k; // overwritten unless touch
                    slot[k] = touch * int(batchRecord + count);
                    count += touch;
                }
                if (count < B && first + B < end)
                    continue;
                for (int c = 0; c < count; ++c)
                {
                    const long p = pair[c];
                    owner[c] = pairs.owner[p];
                    partner[c] = pairs.partner[p];
                    for (int v = 0; v < kHistory; ++v)
                        history[v * kBatch + c] = pairs.history[p + v * hs];
                }
                // The test's staging area is free again: the chunks' positions go there too.
                for (int c0 = 0; c0 < count; c0 += kChunk)
                {
                    const int chunk = std::min(kChunk, count - c0);
                    staging::stageRecords<4>(positions, owner + c0, chunk, positionI, kChunk);
                    staging::stageRecords<4>(positions, partner + c0, chunk, positionJ, kChunk);
                    staging::stageRecords<8>(velocities, owner + c0, chunk, velocityI, kChunk);
                    staging::stageRecords<8>(velocities, partner + c0, chunk, velocityJ, kChunk);
#pragma omp simd
                    for (int c = 0; c < chunk; ++c)
                    {
                        const PairGrainRecords staged{positionI + c, positionJ + c, velocityI + c,
                                                      velocityJ + c, kChunk};
                        local.evaluate(owner[c0 + c], partner[c0 + c], staged, history + c0 + c,
                                       kBatch, batchRecord + c0 + c);
                    }
                }
                for (int c = 0; c < count; ++c)
                    for (int v = 0; v < kHistory; ++v)
                        pairs.history[pair[c] + v * hs] = history[v * kBatch + c];
                for (int c = 0; c < count; ++c)
                    pairs.markMayTouch(owner[c], partner[c]);
                batchRecord += count;
                count = 0;
            }
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

private:
    AdaptiveThreads team_;
    double stepStart_ = 0.0;
};

} // namespace detail
} // namespace dem

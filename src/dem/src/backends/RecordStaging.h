// RecordStaging.h
// CPU backend only (GCC vector extensions): copies the packed records of the grains a block of
// pairs names (GrainView::packedPositionRadius, 4 doubles per grain; packedVelocities, 8) into
// a staging area field by field, so that the vectorised pair test and contact law read
// contiguous vectors instead of loading every field of every grain element by element. Eight
// grains at a time: each 4-double part of a record read as one vector and the 8 x 4 block
// transposed in registers (with AVX-512 12 shuffles where element loads took 32 loads, some 28
// inserts and the extraction of eight indices per vector; the shuffle port is the limit of
// both), as two 4 x 4 blocks where the target has 256-bit registers only.
// Copies values only: the kernels' arithmetic, and so every bit of the results, is unchanged.
#pragma once

#include <cstring>

namespace dem
{
namespace detail
{
namespace staging
{

typedef double Lanes4 __attribute__((vector_size(32)));
typedef double Lanes8 __attribute__((vector_size(64)));

//- Loads 4 doubles from an address aligned to 8 bytes only.
inline Lanes4 loadLanes4(const double* p)
{
    Lanes4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

//- Stores a vector (Lanes4 or Lanes8) at an address aligned to 8 bytes only.
template <class Lanes>
inline void storeLanes(double* p, const Lanes& v)
{
    std::memcpy(p, &v, sizeof v);
}

//- With 512-bit registers (AVX-512): the 8 x 4 block in 12 shuffles of 8-lane vectors.
inline void transposeEightIn512(const double* records, long recordSize, const int* index,
                                double* rows, long stride)
{
    Lanes4 a[8];
    for (int k = 0; k < 8; ++k)
        a[k] = loadLanes4(records + recordSize * index[k]);
    // Pairs of records side by side: grains k and k + 4 in one 8-lane vector.
    const Lanes8 z0 = __builtin_shufflevector(a[0], a[4], 0, 1, 2, 3, 4, 5, 6, 7);
    const Lanes8 z1 = __builtin_shufflevector(a[1], a[5], 0, 1, 2, 3, 4, 5, 6, 7);
    const Lanes8 z2 = __builtin_shufflevector(a[2], a[6], 0, 1, 2, 3, 4, 5, 6, 7);
    const Lanes8 z3 = __builtin_shufflevector(a[3], a[7], 0, 1, 2, 3, 4, 5, 6, 7);
    // Interleave fields 0 and 2 (even) and 1 and 3 (odd) of grains 0, 1 (4, 5) and 2, 3 (6, 7).
    const Lanes8 even01 = __builtin_shufflevector(z0, z1, 0, 8, 2, 10, 4, 12, 6, 14);
    const Lanes8 odd01 = __builtin_shufflevector(z0, z1, 1, 9, 3, 11, 5, 13, 7, 15);
    const Lanes8 even23 = __builtin_shufflevector(z2, z3, 0, 8, 2, 10, 4, 12, 6, 14);
    const Lanes8 odd23 = __builtin_shufflevector(z2, z3, 1, 9, 3, 11, 5, 13, 7, 15);
    storeLanes(rows, __builtin_shufflevector(even01, even23, 0, 1, 8, 9, 4, 5, 12, 13)); // field 0
    storeLanes(rows + stride,
               __builtin_shufflevector(odd01, odd23, 0, 1, 8, 9, 4, 5, 12, 13)); // field 1
    storeLanes(rows + 2 * stride,
               __builtin_shufflevector(even01, even23, 2, 3, 10, 11, 6, 7, 14, 15)); // field 2
    storeLanes(rows + 3 * stride,
               __builtin_shufflevector(odd01, odd23, 2, 3, 10, 11, 6, 7, 14, 15)); // field 3
}

//- With 256-bit registers only (AVX2): two 4 x 4 blocks, 8 shuffles each. GCC has no 8-lane
//- vector there and splits transposeEightIn512's shuffles element by element through the
//- stack: on an AMD EPYC without AVX-512 the static benchmark ran at 0.54 of its speed with
//- them (src/dem/bench/RECORD.md, "6 Dec 2026, morning").
inline void transposeEightIn256(const double* records, long recordSize, const int* index,
                                double* rows, long stride)
{
    for (int half = 0; half < 8; half += 4)
    {
        Lanes4 a[4];
        for (int k = 0; k < 4; ++k)
            a[k] = loadLanes4(records + recordSize * index[half + k]);
        // Fields 0 and 2 (even), 1 and 3 (odd) of grains 0, 1 and of grains 2, 3, interleaved.
        const Lanes4 even01 = __builtin_shufflevector(a[0], a[1], 0, 4, 2, 6);
        const Lanes4 odd01 = __builtin_shufflevector(a[0], a[1], 1, 5, 3, 7);
        const Lanes4 even23 = __builtin_shufflevector(a[2], a[3], 0, 4, 2, 6);
        const Lanes4 odd23 = __builtin_shufflevector(a[2], a[3], 1, 5, 3, 7);
        double* row = rows + half;
        storeLanes(row, __builtin_shufflevector(even01, even23, 0, 1, 4, 5));              // 0
        storeLanes(row + stride, __builtin_shufflevector(odd01, odd23, 0, 1, 4, 5));       // 1
        storeLanes(row + 2 * stride, __builtin_shufflevector(even01, even23, 2, 3, 6, 7)); // 2
        storeLanes(row + 3 * stride, __builtin_shufflevector(odd01, odd23, 2, 3, 6, 7));   // 3
    }
}

//- Fields 0..3 of the records of grains index[0..7] (grain g's at records + recordSize g)
//- into rows[f * stride + 0..7], f = 0..3, in the widest registers the target has.
inline void transposeEight(const double* records, long recordSize, const int* index, double* rows,
                           long stride)
{
#ifdef __AVX512F__
    transposeEightIn512(records, recordSize, index, rows, stride);
#else
    transposeEightIn256(records, recordSize, index, rows, stride);
#endif
}

//- The kFields-double records of grains index[0 .. count - 1] (grain g's at records +
//- kFields g; kFields a multiple of 4) into stage[f * stride + c] (field f of the c-th grain).
//- Rounds count up to a multiple of 8, repeating the last grain (stride must leave room).
template <int kFields>
inline void stageRecords(const double* records, const int* index, int count, double* stage,
                         long stride)
{
    static_assert(kFields % 4 == 0, "records are staged four fields at a time");
    for (int c = 0; c < count; c += 8)
    {
        int group[8];
        for (int k = 0; k < 8; ++k)
            group[k] = index[c + k < count ? c + k : count - 1];
        for (int f = 0; f < kFields; f += 4)
            transposeEight(records + f, kFields, group, stage + f * stride + c, stride);
    }
}

} // namespace staging
} // namespace detail
} // namespace dem

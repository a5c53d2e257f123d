// RecordStagingTest.cpp
// The CPU pair pass's staging of grain records (src/backends/RecordStaging.h), positions (4
// fields) and velocities (8): field f of the c-th listed grain lands at stage[f * stride + c]
// unchanged, bit for bit, for every list length (whole groups of eight and the tails, which
// repeat the last grain), grains listed in any order and more than once; nothing past the list
// rounded up to eight is written. Compiled with the library's -march=native, so that the test
// runs the same vector code; both transposes (512-bit and 256-bit registers) are checked
// directly too, whichever one this target's stageRecords uses.
#include "backends/RecordStaging.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

using dem::detail::staging::stageRecords;
using dem::detail::staging::transposeEightIn256;
using dem::detail::staging::transposeEightIn512;

namespace
{

template <int kFields>
void checkStaging()
{
    constexpr int kGrains = 100, kStride = 48;
    std::mt19937 random(7);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::uniform_int_distribution<int> grain(0, kGrains - 1);
    std::vector<double> records(kFields * kGrains);
    for (double& x : records)
        x = value(random);
    const double sentinel = -12345.0;
    for (int count = 1; count <= 40; ++count)
    {
        std::vector<int> index(count);
        for (int& i : index)
            i = grain(random);
        std::vector<double> stage(kFields * kStride, sentinel);
        stageRecords<kFields>(records.data(), index.data(), count, stage.data(), kStride);
        const int written = (count + 7) / 8 * 8;
        for (int f = 0; f < kFields; ++f)
            for (int c = 0; c < kStride; ++c)
            {
                const double got = stage[f * kStride + c];
                if (c < written)
                {
                    const int from = index[c < count ? c : count - 1]; // tails repeat the last
                    EXPECT_EQ(std::memcmp(&got, &records[kFields * from + f], sizeof got), 0)
                        << "count " << count << ", field " << f << ", grain " << c;
                }
                else
                    EXPECT_EQ(got, sentinel) << "count " << count << ": wrote past the list";
            }
    }
}

//- Fields first .. first + 3 of eight records (of recordSize doubles, listed in any order and
//- one twice) into rows of a stride that is not a multiple of 4; nothing else written.
template <class Transpose>
void checkTranspose(Transpose transpose, int recordSize, int first)
{
    constexpr int kGrains = 12, kStride = 11;
    std::vector<double> records(recordSize * kGrains);
    for (std::size_t k = 0; k < records.size(); ++k)
        records[k] = 0.1 * double(k) - 3.0;
    const int index[8] = {5, 0, 11, 3, 3, 7, 1, 9};
    const double sentinel = -12345.0;
    std::vector<double> rows(4 * kStride, sentinel);
    transpose(records.data() + first, recordSize, index, rows.data(), kStride);
    for (int f = 0; f < 4; ++f)
        for (int c = 0; c < kStride; ++c)
        {
            const double got = rows[f * kStride + c];
            if (c < 8)
                EXPECT_EQ(got, records[recordSize * index[c] + first + f])
                    << "record size " << recordSize << ", field " << f << ", grain " << c;
            else
                EXPECT_EQ(got, sentinel) << "wrote past the eight grains";
        }
}

} // namespace

TEST(RecordStaging, BothTransposesMoveEightRecordsUnchanged)
{
    for (const int recordSize : {4, 8})
        for (int first = 0; first < recordSize; first += 4)
        {
            checkTranspose(transposeEightIn512, recordSize, first);
            checkTranspose(transposeEightIn256, recordSize, first);
        }
}

TEST(RecordStaging, PositionsLandFieldByFieldUnchanged)
{
    checkStaging<4>();
}

TEST(RecordStaging, VelocitiesLandFieldByFieldUnchanged)
{
    checkStaging<8>();
}

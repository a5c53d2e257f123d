// AdaptiveThreadsTest.cpp
// The CPU backend's choice of its team size from step to step (src/backends/AdaptiveThreads.h),
// fed with step times of a model machine on which one team size is the faster (as a small bed
// on a quiet or on a loaded machine): the policy settles on the faster size, follows a change of
// the load within its longest hold, spends at most about one window in kMaxHold + 2 on probes in
// a steady run, and leaves a fixed thread count (Parameters::threads > 0) alone. The step
// times are those of the model, so the outcome does not depend on this machine. That the
// switches change no bit of the results is asserted where the steps run
// (tests/coupled/test_thread_count.py).
#include "backends/AdaptiveThreads.h"

#include <gtest/gtest.h>

#include <functional>

using dem::detail::AdaptiveThreads;

namespace
{

//- Runs `steps` steps whose time on a team of t threads is secondsFor(step, t).
void run(AdaptiveThreads& team, long steps,
         const std::function<double(long step, int threads)>& secondsFor, long first = 0)
{
    for (long s = first; s < first + steps; ++s)
        team.stepTook(secondsFor(s, team.team()));
}

constexpr double kStep = 1e-3; //!< seconds per step on the slower team: 50 steps a window

} // namespace

TEST(AdaptiveThreads, FixedThreadCountIsKept)
{
    AdaptiveThreads fixed(2, false);
    run(fixed, 20000, [](long, int t) { return t == 2 ? 10 * kStep : kStep; });
    EXPECT_EQ(fixed.team(), 2);
    EXPECT_EQ(fixed.use().probes, 0);
    EXPECT_EQ(fixed.use().stepsOnMost, 20000);

    AdaptiveThreads single(1, true); // one thread: nothing to choose
    EXPECT_FALSE(single.use().adaptive);
    run(single, 1000, [](long, int) { return kStep; });
    EXPECT_EQ(single.team(), 1);
    EXPECT_EQ(single.use().probes, 0);
}

TEST(AdaptiveThreads, KeepsAllThreadsWhereTheyAreFaster)
{
    AdaptiveThreads team(2, true);
    const long steps = 100000; // 100 s of the model
    run(team, steps, [](long, int t) { return t == 2 ? 0.55 * kStep : kStep; });
    EXPECT_EQ(team.chosen(), 2);
    EXPECT_EQ(team.use().switches, 0);
    EXPECT_GT(team.use().probes, 0);
    // one window in kMaxHold + 2 once the holds have grown, the short early holds on top
    EXPECT_GT(double(team.use().stepsOnMost) / steps, 1.0 - 2.0 / AdaptiveThreads::kMaxHold);
}

TEST(AdaptiveThreads, FallsBackToOneThreadWhereThatIsFaster)
{
    AdaptiveThreads team(2, true);
    const long steps = 100000;
    run(team, steps, [](long, int t) { return t == 2 ? 2.5 * kStep : kStep; });
    EXPECT_EQ(team.chosen(), 1);
    EXPECT_EQ(team.use().switches, 1); // at the first probe, and never back
    EXPECT_LT(double(team.use().stepsOnMost) / steps, 2.0 / AdaptiveThreads::kMaxHold);
}

TEST(AdaptiveThreads, FollowsAChangeOfTheLoad)
{
    // a quiet machine (two threads faster) that becomes loaded at step `change` (one faster)
    // and quiet again at 2 change
    const long change = 50000;
    auto machine = [&](long s, int t)
    {
        const bool loaded = s >= change && s < 2 * change;
        return t == 2 ? (loaded ? 2.5 : 0.55) * kStep : kStep;
    };
    AdaptiveThreads team(2, true);
    run(team, change, machine);
    ASSERT_EQ(team.chosen(), 2);
    // within the longest hold, a measurement and a probe (windows of at least kWindowSteps and
    // kWindowSeconds; the loaded windows are the longer, 2.5 kStep a step)
    const long window = long(AdaptiveThreads::kWindowSeconds / kStep) + 1;
    const long bound = (AdaptiveThreads::kMaxHold + 3) * window;
    run(team, bound, machine, change);
    EXPECT_EQ(team.chosen(), 1);
    run(team, change - bound, machine, change + bound);
    ASSERT_EQ(team.chosen(), 1);
    run(team, bound, machine, 2 * change);
    EXPECT_EQ(team.chosen(), 2);
}

TEST(AdaptiveThreads, EqualTeamsDoNotSwitch)
{
    // within the margin (a second thread that gains 2 %): no switch either way
    AdaptiveThreads team(4, true);
    run(team, 100000, [](long, int t) { return t == 4 ? 0.98 * kStep : kStep; });
    EXPECT_EQ(team.chosen(), 4);
    EXPECT_EQ(team.use().switches, 0);
}

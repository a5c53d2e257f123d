// AdaptiveThreads.h
// CPU backend only: how many threads a step's parallel loops use, chosen while the run goes on
// between one and all that the run may use, by timing both. Which is faster depends on the
// bed, the machine and what else runs on it: a bed of 1200 grains stepped 1.6-1.9 times as fast
// on two threads as on one on a quiet AMD EPYC and 1.6 times on a quiet Intel Xeon, where two
// threads had not paid in beds of 600-2500 grains as long as the per-grain passes stayed on one
// thread; with another busy process on the two cores two threads ran at a quarter to a half of
// one thread's speed (each barrier waits for a descheduled thread; src/dem/README.md, "Threads
// (CPU backend)"). The results do not depend on the thread count (the sums run in a fixed
// order), so a switch changes no bit of them.
//
// The policy: time the current team's steps over a window (at least kWindowSteps steps and
// kWindowSeconds), then one window with the other team size (a probe); the faster per step is
// kept (the other must win by kMargin). Between probes the team holds for a number of windows
// that doubles after every probe that changed nothing (kMinHold up to kMaxHold) and starts
// again from kMinHold after a switch: a steady run probes in one window of about kMaxHold + 2,
// and a change of the load is followed within about kMaxHold windows (3-4 s). Plain C++ (no
// OpenMP, no clock): OmpExecution times the steps and sets the team.
#pragma once

#include "dem/State.h"

#include <algorithm>

namespace dem
{
namespace detail
{

class AdaptiveThreads
{
public:
    static constexpr int kWindowSteps = 10;
    static constexpr double kWindowSeconds = 0.05;
    static constexpr double kMargin = 0.03;
    static constexpr int kMinHold = 4, kMaxHold = 64;

    //- most: the threads the run may use; adaptive: choose between 1 and most (else most, always).
    AdaptiveThreads(int most, bool adaptive) : current_(std::max(most, 1))
    {
        use_.most = current_;
        use_.adaptive = adaptive && use_.most > 1;
    }

    //- most, adaptive, and the counts of steps, probes and switches so far.
    const ThreadUse& use() const { return use_; }
    //- The team size for the next step.
    int team() const { return phase_ == Phase::probe ? other() : current_; }
    //- The team size kept (team() is the other one during a probe).
    int chosen() const { return current_; }

    //- The step just run with team() threads took seconds (read only when use().adaptive);
    //- returns the team size for the next.
    int stepTook(double seconds)
    {
        ++use_.steps;
        use_.stepsOnMost += team() == use_.most;
        if (!use_.adaptive)
            return team();
        ++windowSteps_;
        windowSeconds_ += seconds;
        if (windowSteps_ < kWindowSteps || windowSeconds_ < kWindowSeconds)
            return team();
        const double perStep = windowSeconds_ / windowSteps_;
        windowSteps_ = 0;
        windowSeconds_ = 0.0;
        switch (phase_)
        {
        case Phase::hold:
            if (--holdLeft_ <= 0)
                phase_ = Phase::measure;
            break;
        case Phase::measure: // the current team's time right before the probe
            reference_ = perStep;
            phase_ = Phase::probe;
            break;
        case Phase::probe:
            ++use_.probes;
            if (perStep < (1.0 - kMargin) * reference_)
            {
                current_ = other();
                ++use_.switches;
                hold_ = kMinHold;
            }
            else
                hold_ = std::min(2 * hold_, kMaxHold);
            holdLeft_ = hold_;
            phase_ = Phase::hold;
            break;
        }
        return team();
    }

private:
    enum class Phase
    {
        hold,
        measure,
        probe
    };

    int other() const { return current_ == 1 ? use_.most : 1; }

    ThreadUse use_;
    int current_;
    Phase phase_ = Phase::measure; // the first probe after one window
    int hold_ = kMinHold / 2;      // doubled to kMinHold after the first probe that keeps
    int holdLeft_ = 0;
    int windowSteps_ = 0;
    double windowSeconds_ = 0.0;
    double reference_ = 0.0;
};

} // namespace detail
} // namespace dem

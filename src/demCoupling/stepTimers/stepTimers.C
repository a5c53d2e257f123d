/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "stepTimers.H"
#include "objectRegistry.H"
#include "Time.H"

#include <cstdio>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(stepTimers, 0);
}

const char* const Foam::stepTimers::names_[nPhases] =
{
    "DEM steps",
    "deposit",
    "momentum",
    "pressure",
    "gradient",
    "exchange",
    "write"
};

const char* const Foam::stepTimers::otherName_ = "other";


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::stepTimers::scope::scope(stepTimers& timers, const phase p)
:
    timers_(timers),
    phase_(p),
    start_(std::chrono::steady_clock::now())
{}


Foam::stepTimers::stepTimers(const objectRegistry& obr)
:
    regIOobject
    (
        IOobject
        (
            typeName,
            obr.time().constant(),
            obr,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        )
    )
{
    start();
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::stepTimers::scope::~scope()
{
    timers_.add(phase_, since(start_));
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::stepTimers& Foam::stepTimers::New(const objectRegistry& obr)
{
    // One per run: registered on the Time, whichever registry asks
    const objectRegistry& db = obr.time();
    stepTimers* found = db.getObjectPtr<stepTimers>(typeName);
    if (found)
    {
        return *found;
    }
    return regIOobject::store(new stepTimers(db));
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

double Foam::stepTimers::since(const std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::stepTimers::start()
{
    loopStart_ = std::chrono::steady_clock::now();
    seconds_ = 0.0;
    steps_ = 0;
    grainSteps_ = 0;
    intervalStart_ = loopStart_;
    intervalSeconds_ = 0.0;
    intervalSteps_ = 0;
    intervalGrainSteps_ = 0;
}


void Foam::stepTimers::printInterval(Ostream& os)
{
    const double total = since(intervalStart_);
    const double grainSteps = grainSteps_ - intervalGrainSteps_;

    char buf[96];
    std::snprintf
    (
        buf, sizeof(buf), "%.3g s, %d fluid steps, %.3g grain-steps/s;",
        total, int(steps_ - intervalSteps_), total > 0 ? grainSteps/total : 0.0
    );
    os  << "Step timers since the last write: " << buf;

    double other = total;
    for (label p = 0; p < nPhases; ++p)
    {
        const double s = seconds_[p] - intervalSeconds_[p];
        other -= s;
        std::snprintf
        (
            buf, sizeof(buf), " %s %.1f %%,", names_[p],
            total > 0 ? 100*s/total : 0.0
        );
        os  << buf;
    }
    std::snprintf
    (
        buf, sizeof(buf), " %s %.1f %%", otherName_,
        total > 0 ? 100*other/total : 0.0
    );
    os  << buf << endl;

    intervalStart_ = std::chrono::steady_clock::now();
    intervalSeconds_ = seconds_;
    intervalSteps_ = steps_;
    intervalGrainSteps_ = grainSteps_;
}


void Foam::stepTimers::printSummary(Ostream& os) const
{
    const double total = since(loopStart_);
    const double perStep = steps_ > 0 ? 1e3/steps_ : 0;
    char buf[96];

    os  << nl << "Step timers (wall clock of the time loop, " << steps_
        << " fluid steps):" << nl
        << "    phase             seconds        %    ms/step" << nl;

    // '%' of the loop and milliseconds per fluid step, phase by phase
    auto line = [&](const char* name, const double s)
    {
        std::snprintf
        (
            buf, sizeof(buf), "    %-12s %12.3f %8.2f %10.3f",
            name, s, total > 0 ? 100*s/total : 0.0, s*perStep
        );
        os  << buf << nl;
    };

    double other = total;
    for (label p = 0; p < nPhases; ++p)
    {
        line(names_[p], seconds_[p]);
        other -= seconds_[p];
    }
    line(otherName_, other);
    line("total", total);

    std::snprintf
    (
        buf, sizeof(buf), "%.4g grain-steps/s (DEM steps alone: %.4g)",
        total > 0 ? grainSteps_/total : 0.0,
        seconds_[demSteps] > 0 ? grainSteps_/seconds_[demSteps] : 0.0
    );
    os  << "    whole loop: " << buf << nl << endl;
}


// ************************************************************************* //

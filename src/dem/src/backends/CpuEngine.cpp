// CpuEngine.cpp
// The CPU backend: the engine's kernel source compiled by g++ over Thrust's OpenMP system.
#include "backends/OmpExecution.h"
#include "engine/EngineImpl.h"

namespace dem
{
namespace detail
{

std::unique_ptr<Engine> makeCpuEngine(const Parameters& parameters)
{
    if (parameters.threads > 0)
        omp_set_num_threads(parameters.threads);
    return std::make_unique<EngineImpl<OmpExecution>>(parameters);
}

} // namespace detail
} // namespace dem

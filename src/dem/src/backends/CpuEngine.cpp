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
    return std::make_unique<EngineImpl<OmpExecution>>(parameters);
}

} // namespace detail
} // namespace dem

// CudaCheck.cuh
// Checks of CUDA runtime calls and kernel launches where they happen: a failure throws
// dem::Error naming the call, the source file and line, and CUDA's own description. Kernels run
// asynchronously, so a fault inside one is reported by the next synchronising call (a
// reduction's result copy, every step); builds with DEM_CUDA_SYNC_CHECKS (CMake option of the
// same name, on in Debug builds) also synchronise after each launch, so the faulting kernel's
// own launch site is named. Compiled by nvcc only.
#pragma once

#include "dem/Error.h"

#include <thrust/system_error.h>

#include <cuda_runtime.h>

#include <string>

namespace dem
{
namespace detail
{

inline void checkCuda(cudaError_t status, const char* call, const char* file, int line)
{
    if (status != cudaSuccess)
        throw Error(std::string("CUDA error at ") + file + ":" + std::to_string(line) + " in " +
                    call + ": " + cudaGetErrorName(status) + ": " + cudaGetErrorString(status));
}

//- After a kernel launch: launch errors always, the kernel's own faults with
//- DEM_CUDA_SYNC_CHECKS.
inline void checkLaunch(const char* kernel, const char* file, int line)
{
    checkCuda(cudaGetLastError(), kernel, file, line);
#ifdef DEM_CUDA_SYNC_CHECKS
    checkCuda(cudaDeviceSynchronize(), kernel, file, line);
#endif
}

//- Thrust reports a failed CUDA call (also an earlier kernel's fault, seen when it synchronises)
//- as thrust::system_error; at the engine's synchronising calls that becomes a dem::Error too.
template <class F>
auto checkThrust(const F& f, const char* call, const char* file, int line)
{
    try
    {
        return f();
    }
    catch (const thrust::system_error& e)
    {
        throw Error(std::string("CUDA error at ") + file + ":" + std::to_string(line) + " in " +
                    call + ": " + e.what());
    }
}

} // namespace detail
} // namespace dem

//- Wrap every CUDA runtime call: DEM_CUDA_CHECK(cudaMemcpy(...)).
#define DEM_CUDA_CHECK(call) ::dem::detail::checkCuda((call), #call, __FILE__, __LINE__)
//- Around a Thrust call that synchronises: DEM_THRUST_CHECK(thrust::reduce(...)).
#define DEM_THRUST_CHECK(call)                                                                     \
    ::dem::detail::checkThrust([&] { return call; }, #call, __FILE__, __LINE__)
//- After every kernel launch: DEM_CUDA_CHECK_LAUNCH("forEachKernel").
#define DEM_CUDA_CHECK_LAUNCH(kernel) ::dem::detail::checkLaunch(kernel, __FILE__, __LINE__)

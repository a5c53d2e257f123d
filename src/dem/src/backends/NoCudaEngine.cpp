// NoCudaEngine.cpp
// Built instead of CudaEngine.cu when no CUDA compiler was found: the cuda backend refuses.
#include "dem/System.h"
#include "engine/Engine.h"

namespace dem
{

int cudaDeviceCount()
{
    return 0;
}

namespace detail
{

std::unique_ptr<Engine> makeCudaEngine(const Parameters&)
{
    throw Error("backend 'cuda' requested but this build of the DEM library has no CUDA "
                "backend (nvcc was not found at configure time); use backend 'cpu' or 'auto'");
}

} // namespace detail
} // namespace dem

// dem/Error.h
// The single exception type of the DEM library. Every refusal (bad parameter, time step above
// the stability limit, storage overflow, unavailable backend) throws it with a message naming
// the parameter, the offending value and the limit, so callers can turn it into their own
// fatal error (e.g. OpenFOAM's FatalError) without parsing.
#pragma once

#include <stdexcept>
#include <string>

//- Symbols of the public API; everything else in libdem.so is hidden (faster calls, no clashes).
#define DEM_API __attribute__((visibility("default")))

namespace dem
{

class DEM_API Error : public std::runtime_error
{
public:
    explicit Error(const std::string& message) : std::runtime_error("dem: " + message) {}
};

} // namespace dem

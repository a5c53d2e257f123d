/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "demStateFile.H"
#include "error.H"

#include <cstdint>
#include <fstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

const char* const header = "darcyDem-state 1\n";

template<class T>
void writeArrays
(
    std::ofstream& os,
    const std::map<std::string, std::vector<T>>& arrays
)
{
    const std::uint64_t count = arrays.size();
    os.write(reinterpret_cast<const char*>(&count), sizeof count);
    for (const auto& entry : arrays)
    {
        const std::uint64_t nameLength = entry.first.size();
        const std::uint64_t length = entry.second.size();
        os.write(reinterpret_cast<const char*>(&nameLength), sizeof nameLength);
        os.write(entry.first.data(), nameLength);
        os.write(reinterpret_cast<const char*>(&length), sizeof length);
        os.write
        (
            reinterpret_cast<const char*>(entry.second.data()),
            length*sizeof(T)
        );
    }
}

template<class T>
bool readArrays(std::ifstream& is, std::map<std::string, std::vector<T>>& arrays)
{
    std::uint64_t count = 0;
    if (!is.read(reinterpret_cast<char*>(&count), sizeof count))
    {
        return false;
    }
    for (std::uint64_t a = 0; a < count; ++a)
    {
        std::uint64_t nameLength = 0, length = 0;
        if (!is.read(reinterpret_cast<char*>(&nameLength), sizeof nameLength)
         || nameLength > 4096)
        {
            return false;
        }
        std::string name(nameLength, ' ');
        is.read(&name[0], nameLength);
        if (!is.read(reinterpret_cast<char*>(&length), sizeof length)
         || length > (std::uint64_t(1) << 40))
        {
            return false;
        }
        std::vector<T>& values = arrays[name];
        values.resize(length);
        if (!is.read(reinterpret_cast<char*>(values.data()), length*sizeof(T)))
        {
            return false;
        }
    }
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::writeDemState(const fileName& path, const dem::SystemState& state)
{
    std::ofstream os(path, std::ios::binary);
    os.write(header, std::char_traits<char>::length(header));
    writeArrays(os, state.reals);
    writeArrays(os, state.integers);

    if (!os.good())
    {
        FatalErrorInFunction
            << "Cannot write the grain state file " << path << nl
            << exit(FatalError);
    }
}


dem::SystemState Foam::readDemState(const fileName& path)
{
    std::ifstream is(path, std::ios::binary);
    std::string line;
    dem::SystemState state;

    if
    (
        !std::getline(is, line)
     || line + "\n" != header
     || !readArrays(is, state.reals)
     || !readArrays(is, state.integers)
    )
    {
        FatalErrorInFunction
            << "Cannot read the grain state file " << path
            << " (missing, damaged or not written by darcyDem)" << nl
            << exit(FatalError);
    }

    return state;
}


// ************************************************************************* //

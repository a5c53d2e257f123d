/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "demStateFile.H"
#include "atomicFile.H"
#include "error.H"

#include <cstdint>
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

const char* const header = "darcyDem-state 1\n";

template<class T>
void writeArrays
(
    std::ostream& os,
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

//- Read arrays; false with the reason when the file ends early or a
//- length cannot be right
template<class T>
bool readArrays
(
    std::istream& is,
    const char* kind,
    std::map<std::string, std::vector<T>>& arrays,
    std::string& whatIsWrong
)
{
    std::uint64_t count = 0;
    if (!is.read(reinterpret_cast<char*>(&count), sizeof count))
    {
        whatIsWrong = std::string("truncated before the count of ") + kind;
        return false;
    }
    for (std::uint64_t a = 0; a < count; ++a)
    {
        std::uint64_t nameLength = 0, length = 0;
        if (!is.read(reinterpret_cast<char*>(&nameLength), sizeof nameLength)
         || nameLength > 4096)
        {
            whatIsWrong = std::string("truncated or damaged at ") + kind
                + " array " + std::to_string(a) + " of " + std::to_string(count);
            return false;
        }
        std::string name(nameLength, ' ');
        if
        (
            !is.read(&name[0], nameLength)
         || !is.read(reinterpret_cast<char*>(&length), sizeof length)
         || length > (std::uint64_t(1) << 40)
        )
        {
            whatIsWrong = std::string("truncated or damaged at ") + kind
                + " array " + std::to_string(a) + " of " + std::to_string(count);
            return false;
        }
        std::vector<T>& values = arrays[name];
        values.resize(length);
        if (!is.read(reinterpret_cast<char*>(values.data()), length*sizeof(T)))
        {
            whatIsWrong = "truncated inside array '" + name + "' ("
                + std::to_string(length) + " values expected)";
            return false;
        }
    }
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demStateFile::demStateFile(const fileName& path)
:
    path_(path)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::demStateFile::tryRead
(
    dem::SystemState& state,
    std::string& whatIsWrong
) const
{
    std::ifstream is(path_, std::ios::binary);
    if (!is)
    {
        whatIsWrong = "missing or unreadable";
        return false;
    }

    std::string line;
    if (!std::getline(is, line) || line + "\n" != header)
    {
        whatIsWrong = "not a darcyDem state file (first line is not '"
            + std::string(header, std::char_traits<char>::length(header) - 1)
            + "')";
        return false;
    }
    if
    (
        !readArrays(is, "reals", state.reals, whatIsWrong)
     || !readArrays(is, "integers", state.integers, whatIsWrong)
    )
    {
        return false;
    }
    if (is.peek() != std::char_traits<char>::eof())
    {
        whatIsWrong = "bytes after the last array (damaged)";
        return false;
    }
    return true;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::demStateFile::write(const dem::SystemState& state) const
{
    atomicFile::killPoint("beforeDemState");

    // Whole file in memory first: the test hook can stop half-way through
    std::ostringstream bytes(std::ios::binary);
    bytes.write(header, std::char_traits<char>::length(header));
    writeArrays(bytes, state.reals);
    writeArrays(bytes, state.integers);
    const std::string data(bytes.str());

    const atomicFile file(path_);
    {
        std::ofstream os(file.tmpPath(), std::ios::binary);
        os.write(data.data(), data.size()/2);
        os.flush();
        atomicFile::killPoint("inDemState");
        os.write(data.data() + data.size()/2, data.size() - data.size()/2);
        os.close();
        if (!os)
        {
            FatalErrorInFunction
                << "Cannot write the grain state file " << file.tmpPath()
                << nl << exit(FatalError);
        }
    }
    file.commit();

    atomicFile::killPoint("afterDemState");
}


dem::SystemState Foam::demStateFile::read() const
{
    dem::SystemState state;
    std::string whatIsWrong;
    if (!tryRead(state, whatIsWrong))
    {
        FatalErrorInFunction
            << "Cannot read the grain state file " << path_ << ": "
            << whatIsWrong.c_str() << nl
            << "Start from an earlier time, or from a grains file (x y z r"
            << " per line) without contact history." << nl
            << exit(FatalError);
    }
    return state;
}


bool Foam::demStateFile::complete() const
{
    dem::SystemState state;
    std::string whatIsWrong;
    return tryRead(state, whatIsWrong);
}


// ************************************************************************* //

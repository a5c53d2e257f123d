/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "demTable.H"
#include "OStringStream.H"
#include "inputChecks.H"
#include "demLibraryCall.H"
#include "demCloud.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::demTable::demTable
(
    const word& name,
    const Time& runTime,
    const dictionary& dict,
    const word& fileName,
    const string& title
)
:
    fvMeshFunctionObject(name, runTime, dict),
    writeFile(mesh_, name, fileName, dict),
    title_(title),
    headerWritten_(false)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::demTable::read(const dictionary& dict)
{
    // No entries of its own
    inputChecks::checkKnownEntries
    (
        dict,
        inputChecks::functionObjectEntryNames()
    );
    fvMeshFunctionObject::read(dict);
    writeFile::read(dict);
    return true;
}


bool Foam::functionObjects::demTable::execute()
{
    return true;
}


bool Foam::functionObjects::demTable::write()
{
    // Reads of the DEM library: whatever it throws ends as a FatalError
    return demLibraryCall
    (
        "function object " + name(),
        [&]
        {
            const demCloud& cloud = mesh_.lookupObject<demCloud>("demCloud");
            // Every rank makes the row (it sums over the ranks); the master
            // writes it, the only rank with the file (writeFile)
            OStringStream row;
            row.precision(writePrecision_);
            writeRow(row, cloud);
            if (!Pstream::master())
            {
                return true;
            }
            Ostream& os = file();
            if (!headerWritten_)
            {
                writeHeader(os, title_);
                writeCommented(os, "time");
                for (const word& column : columns(cloud))
                {
                    writeTabbed(os, column);
                }
                os << endl;
                headerWritten_ = true;
            }
            writeCurrentTime(os);
            os.writeQuoted(row.str(), false);
            os << endl;
            return true;
        }
    );
}


// ************************************************************************* //

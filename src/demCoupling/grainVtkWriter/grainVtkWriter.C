/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "grainVtkWriter.H"
#include "atomicFile.H"
#include "OFstream.H"
#include "foamVtkSeriesWriter.H"
#include "OSspecific.H"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

void addArray
(
    vtkPolyData* data,
    const char* name,
    const std::vector<double>& values,
    const int components
)
{
    if (values.empty())
    {
        return;
    }
    vtkNew<vtkDoubleArray> array;
    array->SetName(name);
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(values.size()/components);
    std::copy(values.begin(), values.end(), array->GetPointer(0));
    data->GetPointData()->AddArray(array);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::grainVtkWriter::writeVtp
(
    const fileName& path,
    const dem::GrainData& g,
    const bool ascii
)
{
    const vtkIdType n = g.radius.size();

    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(n);
    vtkNew<vtkCellArray> vertices;
    for (vtkIdType i = 0; i < n; ++i)
    {
        points->SetPoint
        (
            i, g.position[3*i], g.position[3*i + 1], g.position[3*i + 2]
        );
        vertices->InsertNextCell(1, &i);
    }

    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    data->SetVerts(vertices);

    addArray(data, "radius", g.radius, 1);
    addArray(data, "velocity", g.velocity, 3);
    addArray(data, "angularVelocity", g.angularVelocity, 3);
    addArray(data, "displacement", g.displacement, 3);
    addArray(data, "force", g.force, 3);
    addArray(data, "fluidForce", g.fluidForce, 3);

    vtkNew<vtkIntArray> contacts;
    contacts->SetName("contactCount");
    contacts->SetNumberOfTuples(n);
    vtkNew<vtkIntArray> flags;
    flags->SetName("flag");
    flags->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
        contacts->SetValue(i, g.contactCount[i]);
        flags->SetValue(i, static_cast<int>(g.flag[i]));
    }
    data->GetPointData()->AddArray(contacts);
    data->GetPointData()->AddArray(flags);

    // Whole or not at all (temporary renamed into place, see atomicFile):
    // a reader (ParaView following a running case) never sees half a file
    const atomicFile file(path);
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(file.tmpPath().c_str());
    writer->SetInputData(data);
    if (ascii)
    {
        writer->SetDataModeToAscii();
    }
    else
    {
        writer->SetDataModeToBinary();
    }
    if (!writer->Write())
    {
        FatalErrorInFunction
            << "VTK could not write " << path << nl << exit(FatalError);
    }
    file.commit();
}


void Foam::grainVtkWriter::writeSeries
(
    const fileName& seriesPath,
    const fileName& vtp,
    const scalar t
)
{
    if (vtp.path() != seriesPath.path())
    {
        FatalErrorInFunction
            << vtp << " is not beside the series file " << seriesPath
            << exit(FatalError);
    }

    vtk::seriesWriter series;
    series.load(seriesPath, true, t);
    series.append(t, vtp);

    // Whole or not at all (temporary renamed into place, see atomicFile)
    const atomicFile file(seriesPath);
    {
        OFstream os(file.tmpPath());
        os.precision(17);   // times round-trip exactly, as the time names
        series.print(os);
    }
    file.commit();
}


// ************************************************************************* //

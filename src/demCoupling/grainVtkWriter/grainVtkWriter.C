/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "grainVtkWriter.H"
#include "atomicFile.H"
#include "OFstream.H"
#include "OStringStream.H"
#include "Time.H"
#include "foamVtkSeriesWriter.H"
#include "OSspecific.H"

#include <array>
#include <sstream>

#include <vtkCapsuleSource.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
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


//- The capsule axis R(q) e_z of quaternion q = (w, x, y, z)
std::array<double, 3> axisOf(const double* q)
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    return
    {
        2*(x*z + w*y),
        2*(y*z - w*x),
        1 - 2*(x*x + y*y)
    };
}


//- Rotate v by the unit quaternion q = (w, x, y, z): v + 2 w (u x v)
//- + 2 u x (u x v), u = (x, y, z)
std::array<double, 3> rotate(const double* q, const std::array<double, 3>& v)
{
    const double w = q[0];
    const double u[3] = {q[1], q[2], q[3]};
    const double t[3] =
    {
        2*(u[1]*v[2] - u[2]*v[1]),
        2*(u[2]*v[0] - u[0]*v[2]),
        2*(u[0]*v[1] - u[1]*v[0])
    };
    return
    {
        v[0] + w*t[0] + u[1]*t[2] - u[2]*t[1],
        v[1] + w*t[1] + u[2]*t[0] - u[0]*t[2],
        v[2] + w*t[2] + u[0]*t[1] - u[1]*t[0]
    };
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
    addArray(data, "coreHalfLength", g.coreHalfLength, 1);
    addArray(data, "orientation", g.orientation, 4);
    addArray(data, "volume", g.volume, 1);
    if (g.orientation.size() == 4*g.radius.size())
    {
        std::vector<double> axis(3*n);
        for (vtkIdType i = 0; i < n; ++i)
        {
            const std::array<double, 3> a(axisOf(&g.orientation[4*i]));
            std::copy(a.begin(), a.end(), &axis[3*i]);
        }
        addArray(data, "axis", axis, 3);
    }
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

    writePolyData(path, data, ascii);
}


bool Foam::grainVtkWriter::hasCapsules(const dem::GrainData& g)
{
    for (const double h : g.coreHalfLength)
    {
        if (h > 0)
        {
            return true;
        }
    }
    return false;
}


void Foam::grainVtkWriter::writeSurfaceVtp
(
    const fileName& path,
    const dem::GrainData& g,
    const bool ascii
)
{
    // One template from VTK's own capsule source: radius 1, core length 2,
    // axis y. A template point p belongs to the end s = sign(p_y) of the
    // core; u = p - s e_y is its unit direction from that end. A grain's
    // point is then x + R(q) (r M u + s h e_z), M turning the template's
    // y axis onto the body z axis: a capsule of any r and h from one
    // tessellation (a plain scaling would flatten the caps).
    vtkNew<vtkCapsuleSource> source;
    source->SetRadius(1);
    source->SetCylinderLength(2);
    source->SetThetaResolution(surfaceResolution);
    source->SetPhiResolution(surfaceResolution);
    source->Update();
    vtkPolyData* shape = source->GetOutput();
    const vtkIdType m = shape->GetNumberOfPoints();
    std::vector<std::array<double, 3>> unit(m);
    std::vector<double> end(m);
    for (vtkIdType k = 0; k < m; ++k)
    {
        double p[3];
        shape->GetPoint(k, p);
        end[k] = p[1] < 0 ? -1 : 1;
        // M: rotation by +90 degrees about x, (x, y, z) -> (x, -z, y)
        unit[k] = {p[0], -p[2], p[1] - end[k]};
    }
    vtkCellArray* polys = shape->GetPolys();

    const vtkIdType n = g.radius.size();
    if
    (
        g.coreHalfLength.size() != size_t(n)
     || g.orientation.size() != size_t(4*n)
    )
    {
        FatalErrorInFunction
            << "The DEM library gave no shape or orientation for " << path
            << nl << exit(FatalError);
    }
    vtkNew<vtkPoints> points;   // float: a picture, not data
    points->SetNumberOfPoints(n*m);
    vtkNew<vtkCellArray> cells;
    cells->AllocateExact
    (
        n*polys->GetNumberOfCells(), n*polys->GetNumberOfConnectivityIds()
    );
    vtkNew<vtkIntArray> grain;
    grain->SetName("grain");
    grain->SetNumberOfTuples(n*m);
    vtkNew<vtkFloatArray> displacement;
    displacement->SetName("displacement");
    displacement->SetNumberOfComponents(3);
    displacement->SetNumberOfTuples(n*m);

    std::vector<vtkIdType> ids;
    for (vtkIdType i = 0; i < n; ++i)
    {
        const double* q = &g.orientation[4*i];
        const double r = g.radius[i], h = g.coreHalfLength[i];
        for (vtkIdType k = 0; k < m; ++k)
        {
            const std::array<double, 3> body
            {
                r*unit[k][0], r*unit[k][1], r*unit[k][2] + end[k]*h
            };
            const std::array<double, 3> v(rotate(q, body));
            points->SetPoint
            (
                i*m + k,
                g.position[3*i] + v[0],
                g.position[3*i + 1] + v[1],
                g.position[3*i + 2] + v[2]
            );
            grain->SetValue(i*m + k, int(i));
            displacement->SetTuple(i*m + k, &g.displacement[3*i]);
        }
        const vtkIdType* cell;
        vtkIdType size;
        for (polys->InitTraversal(); polys->GetNextCell(size, cell);)
        {
            ids.assign(cell, cell + size);
            for (vtkIdType& id : ids)
            {
                id += i*m;
            }
            cells->InsertNextCell(size, ids.data());
        }
    }

    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    data->SetPolys(cells);
    data->GetPointData()->AddArray(grain);
    data->GetPointData()->AddArray(displacement);
    writePolyData(path, data, ascii);
}


void Foam::grainVtkWriter::writePolyData
(
    const fileName& path,
    vtkPolyData* data,
    const bool ascii
)
{
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
            << "VTK could not write " << path << nl
            << exit(FatalError);
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

    // The series as vtk::seriesWriter prints it, times to the last bit
    OStringStream exact;
    exact.precision(17);
    series.print(exact);

    // Whole or not at all (temporary renamed into place, see atomicFile)
    const atomicFile file(seriesPath);
    {
        OFstream os(file.tmpPath());
        os  << timesAsNames(exact.str()).c_str();
    }
    file.commit();
}


Foam::string Foam::grainVtkWriter::timesAsNames(const string& json)
{
    // Each entry is one line: { "name" : "<file>", "time" : <value> }.
    // The value becomes the time's directory name (Time::timeName: the
    // case's timeFormat and timePrecision), as the user and ParaView's
    // OpenFOAM reader see the time: 0.03, not 0.029999999999999999 (the
    // double nearest 0.03 in 17 digits). Entries read back from an
    // earlier run's series are named the same way
    static const std::string key("\"time\" : ");
    std::istringstream in(json);
    std::ostringstream out;
    std::string line;
    while (std::getline(in, line))
    {
        const auto begin = line.find(key);
        const auto end =
        (
            begin == std::string::npos
          ? std::string::npos
          : line.find(' ', begin + key.size())
        );
        if (end != std::string::npos)
        {
            const std::string value
            (
                line.substr(begin + key.size(), end - begin - key.size())
            );
            line.replace
            (
                begin + key.size(),
                value.size(),
                Time::timeName(readScalar(value))
            );
        }
        out << line << '\n';
    }
    return out.str();
}


// ************************************************************************* //

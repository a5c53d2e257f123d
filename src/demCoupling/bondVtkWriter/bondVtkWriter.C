/*---------------------------------------------------------------------------*\
    darcyDem: CFD-DEM for water-saturated granular material
    Licence: GPL-3.0-or-later (links OpenFOAM v1912)
\*---------------------------------------------------------------------------*/

#include "bondVtkWriter.H"
#include "grainVtkWriter.H"
#include "error.H"

#include <cmath>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- A named cell array of one component per bond
template<class Array>
vtkNew<Array>& named(vtkNew<Array>& array, const char* name, vtkIdType n)
{
    array->SetName(name);
    array->SetNumberOfTuples(n);
    return array;
}

//- Length of the 3-vector at v
double magnitude(const double* v)
{
    return std::sqrt(v[0]*v[0] + v[1]*v[1] + v[2]*v[2]);
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bondVtkWriter::writeVtp
(
    const fileName& path,
    const dem::BondData& bonds,
    const dem::GrainData& grains,
    const dem::Parameters& parameters,
    const bool ascii
)
{
    const vtkIdType n = bonds.first.size();
    const vtkIdType nGrains = grains.radius.size();
    const auto sized = [n](const auto& values, const vtkIdType perBond)
    {
        return vtkIdType(values.size()) == perBond*n;
    };
    if
    (
        !sized(bonds.second, 1) || !sized(bonds.patchRadius, 1)
     || !sized(bonds.normalForce, 1) || !sized(bonds.shearForce, 3)
     || !sized(bonds.age, 1) || !sized(bonds.softening, 1)
     || !sized(bonds.creepNormal, 1) || !sized(bonds.creepShear, 1)
     || !sized(bonds.creepTwist, 1) || !sized(bonds.creepBend, 1)
     || !sized(bonds.twistMoment, 1) || !sized(bonds.bendMoment, 3)
    )
    {
        FatalErrorInFunction
            << "The DEM library gave incomplete bond data (" << label(n)
            << " bonds) for " << path << nl << exit(FatalError);
    }

    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(2*n);
    vtkNew<vtkCellArray> lines;
    vtkNew<vtkDoubleArray> patchRadius, normalForce, shearForce, age;
    vtkNew<vtkDoubleArray> twistMoment, bendMoment;
    vtkNew<vtkDoubleArray> creepNormal, creepShear, creepTwist, creepBend;
    vtkNew<vtkIntArray> softening, first, second;
    named(patchRadius, "patchRadius", n);
    named(normalForce, "normalForce", n);
    named(shearForce, "shearForce", n);
    named(twistMoment, "twistMoment", n);
    named(bendMoment, "bendMoment", n);
    named(age, "age", n);
    named(softening, "softening", n);
    named(creepNormal, "creepNormal", n);
    named(creepShear, "creepShear", n);
    named(creepTwist, "creepTwist", n);
    named(creepBend, "creepBend", n);
    named(first, "first", n);
    named(second, "second", n);

    for (vtkIdType b = 0; b < n; ++b)
    {
        const int i = bonds.first[b], j = bonds.second[b];
        if (i < 0 || j < 0 || i >= nGrains || j >= nGrains)
        {
            FatalErrorInFunction
                << "The DEM library gave bond " << label(b) << " between"
                << " grains " << i << " and " << j << " of " << label(nGrains)
                << " for " << path << nl << exit(FatalError);
        }
        double a[3], c[3];
        for (int d = 0; d < 3; ++d)
        {
            a[d] = grains.position[3*i + d];
            double delta = grains.position[3*j + d] - a[d];
            if (d < 2 && parameters.periodic[d])
            {
                const double L = parameters.boxUpper[d] - parameters.boxLower[d];
                delta -= L*std::round(delta/L);
            }
            c[d] = a[d] + delta;
        }
        points->SetPoint(2*b, a);
        points->SetPoint(2*b + 1, c);
        const vtkIdType ends[2] = {2*b, 2*b + 1};
        lines->InsertNextCell(2, ends);

        patchRadius->SetValue(b, bonds.patchRadius[b]);
        normalForce->SetValue(b, bonds.normalForce[b]);
        shearForce->SetValue(b, magnitude(&bonds.shearForce[3*b]));
        twistMoment->SetValue(b, bonds.twistMoment[b]);
        bendMoment->SetValue(b, magnitude(&bonds.bendMoment[3*b]));
        age->SetValue(b, bonds.age[b]);
        softening->SetValue(b, bonds.softening[b]);
        creepNormal->SetValue(b, bonds.creepNormal[b]);
        creepShear->SetValue(b, bonds.creepShear[b]);
        creepTwist->SetValue(b, bonds.creepTwist[b]);
        creepBend->SetValue(b, bonds.creepBend[b]);
        first->SetValue(b, i);
        second->SetValue(b, j);
    }

    vtkNew<vtkPolyData> data;
    data->SetPoints(points);
    data->SetLines(lines);
    for
    (
        vtkDataArray* array :
        {
            static_cast<vtkDataArray*>(patchRadius.Get()),
            static_cast<vtkDataArray*>(normalForce.Get()),
            static_cast<vtkDataArray*>(shearForce.Get()),
            static_cast<vtkDataArray*>(twistMoment.Get()),
            static_cast<vtkDataArray*>(bendMoment.Get()),
            static_cast<vtkDataArray*>(age.Get()),
            static_cast<vtkDataArray*>(softening.Get()),
            static_cast<vtkDataArray*>(creepNormal.Get()),
            static_cast<vtkDataArray*>(creepShear.Get()),
            static_cast<vtkDataArray*>(creepTwist.Get()),
            static_cast<vtkDataArray*>(creepBend.Get()),
            static_cast<vtkDataArray*>(first.Get()),
            static_cast<vtkDataArray*>(second.Get())
        }
    )
    {
        data->GetCellData()->AddArray(array);
    }

    grainVtkWriter::writePolyData(path, data, ascii);
}


// ************************************************************************* //

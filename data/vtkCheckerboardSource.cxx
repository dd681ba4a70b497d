#include "vtkCheckerboardSource.h"

#include "vtkCellData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkCheckerboardSource);

//------------------------------------------------------------------------------
vtkCheckerboardSource::vtkCheckerboardSource()
{
  this->SetNumberOfInputPorts(0);
}

vtkCheckerboardSource::~vtkCheckerboardSource() = default;

//------------------------------------------------------------------------------
void vtkCheckerboardSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Origin: (" << this->Origin[0] << ", " << this->Origin[1] << ", "
     << this->Origin[2] << ")\n";
  os << indent << "Point1: (" << this->Point1[0] << ", " << this->Point1[1] << ", "
     << this->Point1[2] << ")\n";
  os << indent << "Point2: (" << this->Point2[0] << ", " << this->Point2[1] << ", "
     << this->Point2[2] << ")\n";
  os << indent << "Resolution: " << this->XResolution << " x " << this->YResolution << "\n";
}

//------------------------------------------------------------------------------
int vtkCheckerboardSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(this->Origin);
  plane->SetPoint1(this->Point1);
  plane->SetPoint2(this->Point2);
  plane->SetResolution(this->XResolution, this->YResolution);
  plane->Update();
  vtkPolyData* squares = plane->GetOutput();
  if (squares->GetNumberOfCells() != static_cast<vtkIdType>(this->XResolution) * this->YResolution)
  {
    // vtkPlaneSource refuses collinear or coincident corners and leaves its output empty.
    vtkErrorMacro("The board's corners do not span a plane (Origin, Point1 and Point2 must "
                  "not be collinear); no squares.");
    return 1;
  }
  output->ShallowCopy(squares);
  vtkNew<vtkIntArray> checker;
  checker->SetName("checker");
  checker->SetNumberOfValues(squares->GetNumberOfCells());
  // vtkPlaneSource numbers its cells along Point1 first.
  for (int j = 0; j < this->YResolution; ++j)
  {
    for (int i = 0; i < this->XResolution; ++i)
    {
      checker->SetValue(static_cast<vtkIdType>(j) * this->XResolution + i, (i + j) % 2);
    }
  }
  output->GetCellData()->SetScalars(checker);
  return 1;
}

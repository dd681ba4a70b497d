#include "vtkRefractionSeriesReader.h"

#include "rfDeclaredSizes.h"
#include "rfReadInChild.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkCommand.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkGenericCell.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkObjectFactory.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkRefractionGlassChecker.h>
#include <vtkRectilinearGrid.h>
#include <vtkSTLReader.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStructuredGrid.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLRectilinearGridReader.h>
#include <vtkXMLStructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtksys/Directory.hxx>
#include <vtksys/RegularExpression.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkRefractionSeriesReader);

namespace
{
// Whether VTK's filters can read every cell (a face "f 1 2 99" of an OBJ file over three
// vertices, a polygon of no points, an offset beyond the connectivity are read as they
// stand, and every filter and mapper after them would read beyond the arrays): polygonal
// data as the glass checker checks it, an unstructured grid's cells against their types.
bool CheckConnectivity(vtkDataSet* data, std::string& error)
{
  if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    return vtkRefractionGlassChecker::CheckCells(poly, error);
  }
  auto* grid = vtkUnstructuredGrid::SafeDownCast(data);
  if (!grid || grid->GetNumberOfCells() == 0)
  {
    return true;
  }
  vtkCellArray* cells = grid->GetCells();
  vtkUnsignedCharArray* types = grid->GetCellTypesArray();
  const vtkIdType count = cells->GetNumberOfCells();
  if (!types || types->GetNumberOfValues() != count)
  {
    error = "has " + std::to_string(count) + " cells but " +
      std::to_string(types ? types->GetNumberOfValues() : 0) + " cell types";
    return false;
  }
  vtkDataArray* offsets = cells->GetOffsetsArray();
  const vtkIdType length = cells->GetConnectivityArray()->GetNumberOfValues();
  // The size of each type's cell, asked once per type: a cell of fixed size (a triangle, a
  // hexahedron) is made with its points, one of any size (a polygon, a poly-line) with none;
  // -1 for a type VTK does not know or whose faces the readers take as they stand (polyhedra).
  vtkIdType fixedSizes[256];
  std::fill(std::begin(fixedSizes), std::end(fixedSizes), -2);
  vtkNew<vtkGenericCell> cell;
  vtkIdType previous = static_cast<vtkIdType>(offsets->GetComponent(0, 0));
  for (vtkIdType c = 0; c < count; ++c)
  {
    const vtkIdType next = static_cast<vtkIdType>(offsets->GetComponent(c + 1, 0));
    const unsigned char type = types->GetValue(c);
    if (previous < 0 || next < previous || next > length)
    {
      error = "has a cell (cell " + std::to_string(c) + ") of points " +
        std::to_string(previous) + " to " + std::to_string(next - 1) + " of a connectivity of " +
        std::to_string(length);
      return false;
    }
    if (fixedSizes[type] == -2)
    {
      const bool known = type != VTK_POLYHEDRON &&
        std::string(vtkCellTypes::GetClassNameFromTypeId(type)) != "UnknownClass";
      if (known)
      {
        cell->SetCellType(type);
      }
      fixedSizes[type] = known ? cell->GetNumberOfPoints() : -1;
    }
    const vtkIdType fixed = fixedSizes[type];
    if (fixed < 0)
    {
      error = "has a cell (cell " + std::to_string(c) + ") of a type (" + std::to_string(type) +
        ") this viewer does not read";
      return false;
    }
    const vtkIdType least = type == VTK_EMPTY_CELL ? 0 : std::max<vtkIdType>(fixed, 1);
    const vtkIdType size = next - previous;
    if (size < least || (fixed > 0 && size != fixed))
    {
      error = "has a cell (cell " + std::to_string(c) + ", type " + std::to_string(type) + ") of " +
        std::to_string(size) + " points, not " + std::to_string(fixed > 0 ? fixed : least) +
        (fixed > 0 ? "" : " or more");
      return false;
    }
    previous = next;
  }
  double range[2];
  cells->GetConnectivityArray()->GetRange(range, 0);
  const double points = static_cast<double>(grid->GetNumberOfPoints());
  if (length > 0 && (range[0] < 0.0 || range[1] >= points))
  {
    error = "has a cell naming point (counting from 0) " +
      std::to_string(static_cast<long long>(range[0] < 0.0 ? range[0] : range[1])) +
      ", but there are " + std::to_string(grid->GetNumberOfPoints()) + " points";
    return false;
  }
  return true;
}

std::string Extension(const std::string& path)
{
  return vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
}

bool KnownMeshExtension(const std::string& extension)
{
  static const char* const known[] = { ".vtp", ".vtu", ".vti", ".vts", ".vtr", ".vtk", ".stl",
    ".ply", ".obj" };
  return std::find(std::begin(known), std::end(known), extension) != std::end(known);
}

vtkSmartPointer<vtkAlgorithm> MakeReader(const std::string& path)
{
  const std::string extension = Extension(path);
  auto named = [&path](auto reader) {
    reader->SetFileName(path.c_str());
    return vtkSmartPointer<vtkAlgorithm>(reader);
  };
  if (extension == ".vtp")
    return named(vtkSmartPointer<vtkXMLPolyDataReader>::New());
  if (extension == ".vtu")
    return named(vtkSmartPointer<vtkXMLUnstructuredGridReader>::New());
  if (extension == ".vti")
    return named(vtkSmartPointer<vtkXMLImageDataReader>::New());
  if (extension == ".vts")
    return named(vtkSmartPointer<vtkXMLStructuredGridReader>::New());
  if (extension == ".vtr")
    return named(vtkSmartPointer<vtkXMLRectilinearGridReader>::New());
  if (extension == ".vtk")
    return named(vtkSmartPointer<vtkDataSetReader>::New());
  if (extension == ".stl")
    return named(vtkSmartPointer<vtkSTLReader>::New());
  if (extension == ".ply")
    return named(vtkSmartPointer<vtkPLYReader>::New());
  if (extension == ".obj")
    return named(vtkSmartPointer<vtkOBJReader>::New());
  return nullptr;
}

// Collects the readers' error messages instead of letting them print on their own, so that
// the caller can put them in one message that names the file.
void KeepError(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* message = static_cast<std::string*>(clientData);
  if (message->empty() && callData)
  {
    *message = static_cast<const char*>(callData);
    while (!message->empty() && (message->back() == '\n' || message->back() == ' '))
    {
      message->pop_back();
    }
  }
}
}

//------------------------------------------------------------------------------
vtkRefractionSeriesReader::vtkRefractionSeriesReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
const char* vtkRefractionSeriesReader::GetKnownExtensions()
{
  return ".vtp .vtu .vti .vts .vtr .vtk .stl .ply .obj, series as .pvd";
}

//------------------------------------------------------------------------------
bool vtkRefractionSeriesReader::Fail(const std::string& message)
{
  this->LastError = message;
  return false;
}

//------------------------------------------------------------------------------
bool vtkRefractionSeriesReader::SetFileName(const std::string& path, bool numberedSeries)
{
  this->Files.clear();
  this->Times.clear();
  this->LastError.clear();
  this->LoadedIndex = static_cast<size_t>(-1);
  this->Loaded = nullptr;
  this->Modified();
  if (!vtksys::SystemTools::FileExists(path, true))
  {
    return this->Fail("no such file: '" + path + "'");
  }
  const std::string extension = Extension(path);
  if (extension == ".pvd")
  {
    vtkNew<vtkXMLDataParser> parser;
    parser->SetFileName(path.c_str());
    vtkNew<vtkCallbackCommand> quiet;
    std::string parseError;
    quiet->SetCallback(KeepError);
    quiet->SetClientData(&parseError);
    parser->AddObserver(vtkCommand::ErrorEvent, quiet);
    if (!parser->Parse() || !parser->GetRootElement())
    {
      return this->Fail("cannot parse '" + path + "' as a ParaView collection (.pvd)" +
        (parseError.empty() ? "" : ": " + parseError));
    }
    vtkXMLDataElement* collection = parser->GetRootElement()->FindNestedElementWithName("Collection");
    const std::string folder = vtksys::SystemTools::GetFilenamePath(path);
    std::vector<std::pair<double, std::string>> entries;
    for (int i = 0; collection && i < collection->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* dataSet = collection->GetNestedElement(i);
      const char* file = dataSet->GetAttribute("file");
      const char* part = dataSet->GetAttribute("part");
      if (!dataSet->GetName() || std::string(dataSet->GetName()) != "DataSet" || !file ||
        (part && std::atoi(part) != 0))
      {
        continue; // Only the first part of each time step: one mesh per time.
      }
      double time = static_cast<double>(entries.size());
      dataSet->GetScalarAttribute("timestep", time);
      const std::string full = vtksys::SystemTools::FileIsFullPath(file)
        ? std::string(file)
        : vtksys::SystemTools::CollapseFullPath(file, folder);
      entries.emplace_back(time, full);
    }
    if (entries.empty())
    {
      return this->Fail("'" + path + "' lists no data sets (no <Collection><DataSet file=...>)");
    }
    std::stable_sort(entries.begin(), entries.end(),
      [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& entry : entries)
    {
      if (!vtksys::SystemTools::FileExists(entry.second, true))
      {
        return this->Fail("'" + path + "' names a missing file: '" + entry.second + "'");
      }
      if (!KnownMeshExtension(Extension(entry.second)))
      {
        return this->Fail("'" + path + "' names '" + entry.second + "', of an unknown type");
      }
      this->Times.push_back(entry.first);
      this->Files.push_back(entry.second);
    }
    return true;
  }
  if (!KnownMeshExtension(extension))
  {
    return this->Fail("'" + path + "': unknown file type '" + extension + "' (known: " +
      GetKnownExtensions() + ")");
  }
  if (!numberedSeries)
  {
    this->Files.push_back(path);
    this->Times.push_back(0.0);
    return true;
  }

  // A numbered series: name_0007.vtp -> every name_<digits>.vtp beside it.
  const std::string stem = vtksys::SystemTools::GetFilenameWithoutLastExtension(
    vtksys::SystemTools::GetFilenameName(path));
  vtksys::RegularExpression numbered("^(.*[^0-9]|)([0-9]+)$");
  if (!numbered.find(stem))
  {
    return this->Fail("--series: '" + path + "' has no number before its extension " +
      "(expected e.g. name_0000" + extension + ")");
  }
  const std::string prefix = numbered.match(1);
  std::string folder = vtksys::SystemTools::GetFilenamePath(path);
  vtksys::Directory directory;
  if (!directory.Load(folder.empty() ? "." : folder))
  {
    return this->Fail("cannot list the folder of '" + path + "'");
  }
  std::vector<std::pair<long long, std::string>> entries;
  for (unsigned long i = 0; i < directory.GetNumberOfFiles(); ++i)
  {
    const std::string name = directory.GetFile(i);
    if (Extension(name) != extension)
    {
      continue;
    }
    const std::string otherStem = vtksys::SystemTools::GetFilenameWithoutLastExtension(name);
    if (otherStem.size() <= prefix.size() || otherStem.compare(0, prefix.size(), prefix) != 0)
    {
      continue;
    }
    const std::string digits = otherStem.substr(prefix.size());
    if (digits.find_first_not_of("0123456789") != std::string::npos)
    {
      continue;
    }
    entries.emplace_back(std::atoll(digits.c_str()),
      folder.empty() ? name : folder + "/" + name);
  }
  std::sort(entries.begin(), entries.end());
  for (const auto& entry : entries)
  {
    this->Times.push_back(static_cast<double>(entry.first));
    this->Files.push_back(entry.second);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkRefractionSeriesReader::SetFileNames(const std::vector<std::string>& paths)
{
  std::vector<std::string> files;
  for (const std::string& path : paths)
  {
    if (!this->SetFileName(path, false))
    {
      return false;
    }
    if (this->Files.size() != 1 || this->Files[0] != path)
    {
      return this->Fail("'" + path + "': a .pvd collection cannot be one of several inputs");
    }
    files.push_back(path);
  }
  this->Files = files;
  this->Times.resize(files.size());
  std::iota(this->Times.begin(), this->Times.end(), 0.0);
  return !files.empty() || this->Fail("no input files");
}

//------------------------------------------------------------------------------
bool vtkRefractionSeriesReader::ReadIndex(size_t index)
{
  if (index == this->LoadedIndex && this->Loaded)
  {
    return true;
  }
  if (index >= this->Files.size())
  {
    return this->Fail("no input files");
  }
  const std::string& path = this->Files[index];
  vtkSmartPointer<vtkAlgorithm> reader = MakeReader(path);
  if (!reader)
  {
    return this->Fail("'" + path + "': unknown file type");
  }
  std::string unreadable;
  if (!rfCheckDeclaredSizes(path, unreadable))
  {
    return this->Fail("cannot read '" + path + "': " + unreadable);
  }
  if (!rfReadsWithoutCrashing(reader, unreadable))
  {
    return this->Fail("cannot read '" + path + "': " + unreadable);
  }
  std::string readerError;
  vtkNew<vtkCallbackCommand> keep;
  keep->SetCallback(KeepError);
  keep->SetClientData(&readerError);
  reader->AddObserver(vtkCommand::ErrorEvent, keep);
  reader->Update();
  vtkDataObject* data = reader->GetOutputDataObject(0);
  vtkDataSet* dataSet = vtkDataSet::SafeDownCast(data);
  if (!readerError.empty() || !dataSet || dataSet->GetNumberOfPoints() == 0)
  {
    return this->Fail("cannot read '" + path + "': " +
      (!readerError.empty() ? readerError
                            : std::string(dataSet ? "it holds no points" : "not a data set")));
  }
  std::string broken;
  if (!CheckConnectivity(dataSet, broken))
  {
    return this->Fail("cannot use '" + path + "': it " + broken);
  }
  this->Loaded = data;
  this->LoadedIndex = index;
  return true;
}

//------------------------------------------------------------------------------
int vtkRefractionSeriesReader::RequestDataObject(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  if (!this->ReadIndex(0))
  {
    vtkErrorMacro(<< this->LastError);
    return 0;
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataObject* output = outInfo->Get(vtkDataObject::DATA_OBJECT());
  if (!output || !output->IsA(this->Loaded->GetClassName()))
  {
    vtkSmartPointer<vtkDataObject> fresh;
    fresh.TakeReference(this->Loaded->NewInstance());
    outInfo->Set(vtkDataObject::DATA_OBJECT(), fresh);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkRefractionSeriesReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  // Structured data: filters downstream (the contour of a volume) ask for an extent, and
  // without the whole extent they would ask for none. The first file's extent stands for
  // the series.
  int extent[6] = { 0, -1, 0, -1, 0, -1 };
  if (auto* image = vtkImageData::SafeDownCast(this->Loaded))
  {
    image->GetExtent(extent);
    outInfo->Set(vtkDataObject::SPACING(), image->GetSpacing(), 3);
    outInfo->Set(vtkDataObject::ORIGIN(), image->GetOrigin(), 3);
  }
  else if (auto* rectilinear = vtkRectilinearGrid::SafeDownCast(this->Loaded))
  {
    rectilinear->GetExtent(extent);
  }
  else if (auto* structured = vtkStructuredGrid::SafeDownCast(this->Loaded))
  {
    structured->GetExtent(extent);
  }
  if (extent[1] >= extent[0])
  {
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  }
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  if (this->Times.size() > 1)
  {
    outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), this->Times.data(),
      static_cast<int>(this->Times.size()));
    double range[2] = { this->Times.front(), this->Times.back() };
    outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkRefractionSeriesReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataObject* output = outInfo->Get(vtkDataObject::DATA_OBJECT());
  size_t index = 0;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()) && this->Times.size() > 1)
  {
    const double time = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    // The last step not after the requested time (the first one before the series starts).
    const auto after = std::upper_bound(this->Times.begin(), this->Times.end(), time);
    index = after == this->Times.begin() ? 0 : static_cast<size_t>(after - this->Times.begin()) - 1;
  }
  this->UpdateProgress(0.0);
  if (!this->ReadIndex(index))
  {
    vtkErrorMacro(<< this->LastError);
    return 0;
  }
  if (!output->IsA(this->Loaded->GetClassName()))
  {
    vtkErrorMacro(<< "'" << this->Files[index] << "' holds a " << this->Loaded->GetClassName()
                  << ", the series started with a " << output->GetClassName());
    return 0;
  }
  output->ShallowCopy(this->Loaded);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), this->Times[index]);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkRefractionSeriesReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Files: " << this->Files.size() << "\n";
  for (size_t i = 0; i < this->Files.size(); ++i)
  {
    os << indent.GetNextIndent() << this->Times[i] << ": " << this->Files[i] << "\n";
  }
}

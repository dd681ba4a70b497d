/**
 * @class   vtkRefractionSeriesReader
 * @brief   Reads one mesh file or a time series of them, answering the pipeline's time.
 *
 * Every file is read with the VTK reader its extension names: .vtp, .vtu, .vti, .vts, .vtr
 * (VTK XML), .vtk (legacy), .stl, .ply, .obj. A series is a list of (file, time) pairs: from
 * a ParaView collection (.pvd: the DataSet elements' "file" and "timestep" attributes,
 * relative to the .pvd's folder), from a numbered file series (name_0000.vtp, name_0001.vtp,
 * ...: the files with the same prefix, extension and a number in place of the digits, in
 * numeric order, the number as the time), or given one by one. The output has the type of
 * the first file (so a series of images can be contoured downstream); it advertises
 * TIME_STEPS and TIME_RANGE, and RequestData reads the file whose time is the last one not
 * after the requested time. The file read last is kept, so asking again for the same time
 * reads nothing. Progress: one event per file read.
 *
 * Errors (a missing file, an unknown extension, a reader that fails, a .pvd without data
 * sets) are reported through vtkErrorMacro and GetLastError(); SetFileName/SetSeries check
 * what they can up front and return false with the message.
 */
#ifndef vtkRefractionSeriesReader_h
#define vtkRefractionSeriesReader_h

#include "vtkDataObjectAlgorithm.h"
#include "vtkSmartPointer.h" // For the kept data set

#include <string> // For file names
#include <vector> // For the series

class vtkRefractionSeriesReader : public vtkDataObjectAlgorithm
{
public:
  static vtkRefractionSeriesReader* New();
  vtkTypeMacro(vtkRefractionSeriesReader, vtkDataObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * One input: a mesh file, a .pvd collection, or with @a numberedSeries the first (any)
   * file of a numbered series. Returns false (and GetLastError()) when the path does not
   * exist, the extension is unknown, the .pvd cannot be parsed, or the series is empty.
   */
  bool SetFileName(const std::string& path, bool numberedSeries);

  /** Several files, one time step each (times 0, 1, 2, ...), checked as SetFileName does. */
  bool SetFileNames(const std::vector<std::string>& paths);

  /** The series as set: file names and their times. */
  const std::vector<std::string>& GetFiles() const { return this->Files; }
  const std::vector<double>& GetTimes() const { return this->Times; }

  /**
   * Reads the first file now: false (and GetLastError()) when it cannot be read or used.
   * For programs that report a bad input with one message of their own before they build
   * a pipeline (an update would also report it, through vtkErrorMacro and the executive).
   */
  bool ReadFirstFile() { return this->ReadIndex(0); }

  /** The last error message, empty when there was none. */
  const std::string& GetLastError() const { return this->LastError; }

  /** The extensions this reader knows, for help texts: ".vtp .vtu ...". */
  static const char* GetKnownExtensions();

protected:
  vtkRefractionSeriesReader();
  ~vtkRefractionSeriesReader() override = default;

  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkRefractionSeriesReader(const vtkRefractionSeriesReader&) = delete;
  void operator=(const vtkRefractionSeriesReader&) = delete;

  bool Fail(const std::string& message);
  bool ReadIndex(size_t index);

  std::vector<std::string> Files;
  std::vector<double> Times;
  std::string LastError;
  size_t LoadedIndex = static_cast<size_t>(-1);
  vtkSmartPointer<vtkDataObject> Loaded;
};

#endif

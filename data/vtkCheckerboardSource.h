/**
 * @class   vtkCheckerboardSource
 * @brief   A plane of XResolution x YResolution squares with alternating cell scalars 0 and 1.
 *
 * The opaque scenery that glass is judged against: a board behind or under the glass shows
 * at once how it bends, squeezes and inverts what is behind it. The output is
 * vtkPlaneSource's (Origin, Point1, Point2, resolutions; cells along Point1 first, point
 * normals) with an int cell array "checker" set as the active cell scalars: 0 where
 * (i + j) is even, 1 where it is odd. Map it through a two-colour lookup table with
 * SetScalarModeToUseCellData() for flat squares.
 *
 * @code
 * vtkNew<vtkCheckerboardSource> board;
 * board->SetOrigin(-2, -1, -3);
 * board->SetPoint1(2, -1, -3);
 * board->SetPoint2(-2, 2, -3);
 * board->SetResolution(8, 6);
 * @endcode
 */

#ifndef vtkCheckerboardSource_h
#define vtkCheckerboardSource_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkRefractionDataModule.h" // For export macro

class VTKREFRACTIONDATA_EXPORT vtkCheckerboardSource : public vtkPolyDataAlgorithm
{
public:
  static vtkCheckerboardSource* New();
  vtkTypeMacro(vtkCheckerboardSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The corner of square (0, 0) and the two corners next to it (default the unit square). */
  vtkSetVector3Macro(Origin, double);
  vtkGetVector3Macro(Origin, double);
  vtkSetVector3Macro(Point1, double);
  vtkGetVector3Macro(Point1, double);
  vtkSetVector3Macro(Point2, double);
  vtkGetVector3Macro(Point2, double);
  ///@}

  ///@{
  /** Squares along Point1 and along Point2 (default 8 x 8, 1 to 4096 each). */
  vtkSetClampMacro(XResolution, int, 1, 4096);
  vtkGetMacro(XResolution, int);
  vtkSetClampMacro(YResolution, int, 1, 4096);
  vtkGetMacro(YResolution, int);
  void SetResolution(int x, int y)
  {
    this->SetXResolution(x);
    this->SetYResolution(y);
  }
  ///@}

protected:
  vtkCheckerboardSource();
  ~vtkCheckerboardSource() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCheckerboardSource(const vtkCheckerboardSource&) = delete;
  void operator=(const vtkCheckerboardSource&) = delete;

  double Origin[3] = { 0.0, 0.0, 0.0 };
  double Point1[3] = { 1.0, 0.0, 0.0 };
  double Point2[3] = { 0.0, 1.0, 0.0 };
  int XResolution = 8;
  int YResolution = 8;
};

#endif

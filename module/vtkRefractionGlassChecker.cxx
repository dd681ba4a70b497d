#include "vtkRefractionGlassChecker.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkMapper.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProp.h"
#include "vtkProp3DCollection.h"
#include "vtkPropAssembly.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRefractionGlassKeys.h"
#include "vtkRefractionMeshes.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"

#include "rf_validate.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkRefractionGlassChecker);

namespace
{
std::string Address(const void* pointer)
{
  std::ostringstream text;
  text << pointer;
  return text.str();
}
}

//------------------------------------------------------------------------------
void vtkRefractionGlassChecker::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Checked props: " << this->GlassChecks.size() << "\n";
}

//------------------------------------------------------------------------------
void vtkRefractionGlassChecker::SplitProps(const vtkRenderState* s,
  std::vector<vtkProp*>& glass, std::vector<vtkProp*>* others, bool acrossRanks)
{
  this->QuietEmpty = acrossRanks;
  glass.clear();
  if (others)
  {
    others->clear();
  }
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (!vtkRefractionGlassKeys::IsGlass(prop))
    {
      if (others)
      {
        others->push_back(prop);
      }
      continue;
    }
    this->CheckOpacity(prop);
    const int verdict = this->CheckGlassProp(prop);
    if (verdict == GLASS_AS_ORDINARY && others)
    {
      others->push_back(prop);
    }
    else if (verdict == GLASS_OK)
    {
      glass.push_back(prop);
    }
  }
  this->CheckAssemblies(s);
  // Glass props the renderer culled never reach the prop array (an empty vtkPolyData has no
  // bounds and is culled first): they still deserve their message, once (CheckGlassProp).
  vtkPropCollection* viewProps = s->GetRenderer() ? s->GetRenderer()->GetViewProps() : nullptr;
  if (viewProps && viewProps->GetNumberOfItems() > s->GetPropArrayCount())
  {
    vtkProp** arrayEnd = s->GetPropArray() + s->GetPropArrayCount();
    vtkCollectionSimpleIterator it;
    viewProps->InitTraversal(it);
    while (vtkProp* prop = viewProps->GetNextProp(it))
    {
      if (prop->GetVisibility() && vtkRefractionGlassKeys::IsGlass(prop) &&
        std::find(s->GetPropArray(), arrayEnd, prop) == arrayEnd)
      {
        this->CheckGlassProp(prop);
      }
    }
  }
  if (acrossRanks && viewProps)
  {
    glass.clear();
    vtkCollectionSimpleIterator it;
    viewProps->InitTraversal(it);
    while (vtkProp* prop = viewProps->GetNextProp(it))
    {
      if (prop->GetVisibility() && vtkRefractionGlassKeys::IsGlass(prop))
      {
        const int verdict = this->CheckGlassProp(prop);
        if (verdict == GLASS_OK || verdict == GLASS_EMPTY)
        {
          glass.push_back(prop);
        }
      }
    }
  }
  if (this->GlassChecks.size() > 4 * glass.size() + 16)
  {
    this->GlassChecks.clear(); // entries of props that went away
    this->WarnedOpacity.clear();
    this->WarnedAssemblyParts.clear();
  }
}

//------------------------------------------------------------------------------
void vtkRefractionGlassChecker::CheckAssemblies(const vtkRenderState* s)
{
  // An assembly draws its parts itself, each with the assembly's matrix poked into it, so a
  // part never comes to the pass as a prop of its own: marked glass, it is drawn as the
  // assembly draws it. Said once per part.
  std::vector<std::pair<vtkProp*, vtkProp*>> stack; // (part, its outermost assembly)
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    stack.emplace_back(s->GetPropArray()[i], s->GetPropArray()[i]);
  }
  std::set<vtkProp*> seen;
  while (!stack.empty())
  {
    vtkProp* prop = stack.back().first;
    vtkProp* assembly = stack.back().second;
    stack.pop_back();
    if (!seen.insert(prop).second)
    {
      continue;
    }
    vtkPropCollection* parts = nullptr;
    if (auto* a = vtkAssembly::SafeDownCast(prop))
    {
      parts = a->GetParts();
    }
    else if (auto* pa = vtkPropAssembly::SafeDownCast(prop))
    {
      parts = pa->GetParts();
    }
    if (parts)
    {
      vtkCollectionSimpleIterator it;
      parts->InitTraversal(it);
      while (vtkProp* part = parts->GetNextProp(it))
      {
        stack.emplace_back(part, assembly);
      }
    }
    else if (prop != assembly && vtkRefractionGlassKeys::IsGlass(prop) &&
      this->WarnedAssemblyParts.insert(prop).second)
    {
      vtkWarningMacro("Glass prop " << prop->GetClassName() << " " << prop << " is a part of "
                                    << assembly->GetClassName() << " " << assembly
                                    << ", which draws its parts itself: it is drawn as an "
                                       "ordinary actor. Add it to the renderer to make it "
                                       "glass (with the assembly's matrix as its user matrix).");
    }
  }
}

//------------------------------------------------------------------------------
void vtkRefractionGlassChecker::CheckOpacity(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  const double opacity = actor && actor->GetProperty() ? actor->GetProperty()->GetOpacity() : 1.0;
  if (!(opacity < 1.0))
  {
    this->WarnedOpacity.erase(prop);
    return;
  }
  auto warned = this->WarnedOpacity.find(prop);
  if (warned != this->WarnedOpacity.end() && warned->second == opacity)
  {
    return;
  }
  this->WarnedOpacity[prop] = opacity;
  // VTK hands translucent actors to its translucent pass, after the opaque step that draws
  // the glass: such an actor never reaches the glass stages.
  vtkWarningMacro("Glass actor " << prop << " has opacity " << opacity
                                 << ": VTK draws translucent actors in its translucent pass, so "
                                    "it is drawn as an ordinary translucent surface, not as "
                                    "glass. Leave glass at opacity 1 (the scene shows through "
                                    "it by refraction) and tint it with its colour.");
}

//------------------------------------------------------------------------------
int vtkRefractionGlassChecker::CheckGlassProp(vtkProp* prop)
{
  vtkMapper* mapper = vtkRefractionMeshes::GetMapper(prop);
  if (mapper && mapper->GetNumberOfInputConnections(0) > 0)
  {
    // What the mapper is about to draw (as GetBounds does; free when up to date).
    mapper->Update();
  }
  const bool composite = vtkRefractionMeshes::IsComposite(prop);
  const std::vector<vtkRefractionMeshes::Block> blocks =
    vtkRefractionMeshes::GetBlocks(prop, true);
  // The verdict depends on the index and on the data only. Not on the prop's or its keys'
  // modification times: every render adds and removes the pass on the keys, and moving an
  // actor should not rescan its points.
  const double ior = vtkRefractionGlassKeys::GetIndexOfRefraction(prop);
  vtkDataObject* data = mapper ? mapper->GetInputDataObject(0, 0) : nullptr;
  vtkMTimeType time = data ? data->GetMTime() : 0;
  for (const auto& block : blocks)
  {
    time = std::max(time, block.Mesh->GetMTime());
  }
  auto cached = this->GlassChecks.find(prop);
  if (cached != this->GlassChecks.end() && cached->second.Time == time &&
    cached->second.Data == data && cached->second.Blocks == blocks.size() &&
    (cached->second.IOR == ior || (std::isnan(cached->second.IOR) && std::isnan(ior))))
  {
    return cached->second.Verdict;
  }
  GlassCheck& check = this->GlassChecks[prop];
  check.Time = time;
  check.Data = data;
  check.Blocks = blocks.size();
  check.IOR = ior;
  check.Verdict = GLASS_OK;

  const rf_status status = rf_validate_ior(ior);
  if (status != RF_OK)
  {
    // The key was set by hand (MakeGlass refuses): draw the prop as an ordinary actor.
    vtkErrorMacro("Glass prop " << prop->GetClassName() << " " << prop
                                << " has index of refraction " << ior << ": "
                                << rf_status_message(status) << ". It is drawn as opaque.");
    check.Verdict = GLASS_AS_ORDINARY;
    return check.Verdict;
  }
  if (mapper && !vtkPolyDataMapper::SafeDownCast(mapper))
  {
    // A vtkGlyph3DMapper, say: its surfaces are made while it draws, out of the glass stages'
    // reach (the geometry they capture and the surface model are a polydata's).
    vtkWarningMacro("Glass prop " << prop->GetClassName() << " " << prop << " is drawn by a "
                                  << mapper->GetClassName()
                                  << ": glass needs a vtkPolyDataMapper or a "
                                     "vtkCompositePolyDataMapper2 (vtkGlyph3D makes glyphs a "
                                     "polydata); it is drawn as an ordinary actor.");
    check.Verdict = GLASS_AS_ORDINARY;
    return check.Verdict;
  }
  if (!data)
  {
    return check.Verdict; // no data set (not a polydata actor): nothing to check here
  }
  const std::string name = std::string(prop->GetClassName()) + " " + Address(prop);
  vtkIdType points = 0;
  vtkIdType cells = 0;
  vtkIdType surfaces = 0;
  vtkIdType verts = 0;
  vtkIdType lines = 0;
  for (const auto& block : blocks)
  {
    const std::string where = vtkRefractionMeshes::DescribeBlock(block, composite);
    std::string error;
    if (!CheckMesh(block.Mesh, error))
    {
      vtkErrorMacro("Glass prop " << name << ": " << where << "its data " << error
                                  << ": the prop is not drawn.");
      check.Verdict = GLASS_SKIPPED;
      return check.Verdict;
    }
    points += block.Mesh->GetNumberOfPoints();
    cells += block.Mesh->GetNumberOfCells();
    surfaces += block.Mesh->GetNumberOfPolys() + block.Mesh->GetNumberOfStrips();
    verts += block.Mesh->GetNumberOfVerts();
    lines += block.Mesh->GetNumberOfLines();
  }
  if (points == 0 || cells == 0)
  {
    check.Verdict = GLASS_EMPTY;
    if (this->QuietEmpty)
    {
      return check.Verdict;
    }
    const std::string what = composite
      ? "composite data set (" + std::to_string(blocks.size()) + " polydata blocks, "
      : std::string("vtkPolyData (");
    vtkWarningMacro("Glass prop " << name << " has an empty " << what << points << " points, "
                                  << cells << " cells): nothing to draw.");
    return check.Verdict;
  }
  if (surfaces == 0)
  {
    vtkWarningMacro("Glass prop " << name << " has no polygons (" << verts << " vertices, "
                                  << lines
                                  << " lines): glass needs surfaces; it is drawn as an ordinary "
                                     "actor.");
    check.Verdict = GLASS_AS_ORDINARY;
  }
  else if ((verts > 0 || lines > 0) && vtkRefractionMeshes::DrawsSurfaces(prop))
  {
    // VTK 9.1's mapper draws a prop's vertices and lines with its polygons, through the glass
    // program, which leaves their fragments out (rfGeometryFS.glsl, RF_SURFACES_ONLY): drawn
    // into the glass, a line left a copy of the surface under it, which PEEL refracted through
    // (the benchmark's torus, whose seam vtkCleanPolyData had made into 572 lines). Said, as
    // they are then drawn nowhere. With the wireframe or points representation they are glass
    // as the polygons' edges or points are: nothing to say.
    vtkWarningMacro("Glass prop " << name << " has " << verts << " vertices and " << lines
                                  << " lines besides its " << surfaces
                                  << " polygons: glass is its surfaces, so they are not drawn. "
                                     "Draw them with an ordinary actor, or drop them "
                                     "(vtkCleanPolyData: ConvertPolysToLinesOff, "
                                     "ConvertLinesToPointsOff).");
  }
  return check.Verdict;
}

//------------------------------------------------------------------------------
bool vtkRefractionGlassChecker::CheckCells(vtkPolyData* poly, std::string& error)
{
  // Every reader of the connectivity (vtkPolyDataNormals' cell links, the mapper's index
  // buffer, the surface model) trusts the offsets and the point ids: a polygon of no points
  // makes VTK's cell map leave the cell without an array (vtkPolyDataNormals then reads
  // through a null pointer), an offset beyond the connectivity or a missing point reads
  // beyond the arrays.
  const vtkIdType points = poly->GetNumberOfPoints();
  vtkCellArray* kinds[4] = { poly->GetVerts(), poly->GetLines(), poly->GetPolys(),
    poly->GetStrips() };
  const char* kindNames[4] = { "vertex", "line", "polygon", "triangle strip" };
  // A polygon or strip of fewer than 3 points bounds nothing, a line of one point is none.
  const vtkIdType leastSizes[4] = { 1, 2, 3, 3 };
  for (int k = 0; k < 4; ++k)
  {
    vtkCellArray* cells = kinds[k];
    if (!cells || cells->GetNumberOfCells() == 0)
    {
      continue;
    }
    vtkDataArray* offsets = cells->GetOffsetsArray();
    const vtkIdType length = cells->GetConnectivityArray()->GetNumberOfValues();
    vtkIdType previous = static_cast<vtkIdType>(offsets->GetComponent(0, 0));
    for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
    {
      const vtkIdType next = static_cast<vtkIdType>(offsets->GetComponent(c + 1, 0));
      const vtkIdType size = next - previous;
      if (size < leastSizes[k] || previous < 0 || next > length)
      {
        std::ostringstream text;
        text << "has a " << kindNames[k] << " cell (cell " << c << " of its " << kindNames[k]
             << "s) of ";
        if (previous < 0 || next > length)
        {
          text << "points " << previous << " to " << next - 1 << " of a connectivity of "
               << length;
        }
        else
        {
          text << size << " points (at least " << leastSizes[k] << ")";
        }
        error = text.str();
        return false;
      }
      previous = next;
    }
    double range[2];
    cells->GetConnectivityArray()->GetRange(range, 0);
    if (range[0] < 0.0 || range[1] >= static_cast<double>(points))
    {
      std::ostringstream text;
      text << "has a " << kindNames[k] << " cell naming point "
           << static_cast<long long>(range[0] < 0.0 ? range[0] : range[1]) << " of " << points
           << " points (ids 0 to " << points - 1 << ")";
      error = text.str();
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkRefractionGlassChecker::CheckMesh(vtkPolyData* poly, std::string& error)
{
  // One scan per modification. NaN or infinite coordinates would reach the capture as NaN
  // depths and normals, which the filtered normal texture spreads to the neighbours.
  if (!CheckCells(poly, error))
  {
    return false;
  }
  const vtkIdType points = poly->GetNumberOfPoints();
  if (points == 0)
  {
    return true;
  }
  vtkDataArray* coordinates = poly->GetPoints()->GetData();
  vtkIdType bad = 0;
  vtkIdType first = -1;
  double firstPoint[3] = { 0.0, 0.0, 0.0 };
  for (vtkIdType i = 0; i < points; ++i)
  {
    double p[3];
    coordinates->GetTuple(i, p);
    // Beyond FLT_MAX, a coordinate is infinite in OpenGL's floats.
    if (!(std::fabs(p[0]) <= FLT_MAX && std::fabs(p[1]) <= FLT_MAX && std::fabs(p[2]) <= FLT_MAX))
    {
      if (bad++ == 0)
      {
        first = i;
        std::copy(p, p + 3, firstPoint);
      }
    }
  }
  if (bad > 0)
  {
    std::ostringstream text;
    text << "has " << bad << " of " << points
         << " points with NaN, infinite or too large coordinates (beyond " << FLT_MAX
         << ", which OpenGL's floats do not hold; the first: point " << first << " = ("
         << firstPoint[0] << ", " << firstPoint[1] << ", " << firstPoint[2] << "))";
    error = text.str();
    return false;
  }
  return true;
}

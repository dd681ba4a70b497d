// vtkRefractionPass across MPI ranks (issue 25): the rank exchange, the compositing of the
// ranks' G-buffers before rank 0 shades, and what it measured. The pass's class, in a file of
// its own so that vtkRefractionPass.cxx stays the ordering of the stages.
#include "vtkRefractionPass.h"

#include "vtkOpenGLError.h"
#include "vtkProp.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkRefractionDepthRange.h"
#include "vtkRefractionGBufferComposite.h"
#include "vtkRefractionGeometryStage.h"
#include "vtkRefractionMethod.h"
#include "vtkRefractionRankExchange.h"
#include "vtkRefractionStageTimers.h"
#include "vtkRefractionTargets.h"

//------------------------------------------------------------------------------
bool vtkRefractionPass::CompositeAcrossRanks(vtkOpenGLRenderer* ren,
  vtkOpenGLRenderWindow* renWin, const std::vector<vtkProp*>& glass, vtkRefractionMethod* method,
  const double background[3], const double background2[3], int peelLayers, bool reduction,
  bool dataColour, bool sceneCapture, bool compositingBackground,
  vtkRefractionRankExchange* exchange)
{
  // Every rank's G-buffers drawn (PEEL's layers too, all of them: a layer empty on one rank
  // may hold glass on another), then merged on rank 0, which shades.
  if (peelLayers > 1)
  {
    this->StageTimers->Start(TIMED_BACK_CAPTURE);
    this->GeometryStage->DrawPeelLayers(ren, this->Targets, peelLayers, false);
    this->PeelLayersDrawn = this->GeometryStage->GetPeelDraws();
    this->PeelFacingCulled = this->GeometryStage->GetPeelByFacing();
    this->StageTimers->Stop(TIMED_BACK_CAPTURE);
  }
  if ((method->NeedsDepthRange() && !reduction) || peelLayers > 1)
  {
    vtkRefractionDepthRange::ComputeBounds(ren, glass, this->BoundsDepthRange);
    this->BoundsDepthRange[0] = exchange->AllReduceMin(this->BoundsDepthRange[0]);
    this->BoundsDepthRange[1] = exchange->AllReduceMax(this->BoundsDepthRange[1]);
  }
  vtkRefractionGBufferComposite::Request request;
  request.FrontColour = dataColour;
  request.FrontAux = method->NeedsNormalDistance();
  request.FrontSH = method->NeedsSHTransfer();
  request.Back = method->NeedsBackSurface();
  request.BackNearest = this->BackSurface == BACK_SURFACE_NEAREST;
  request.PeelLayers = peelLayers;
  request.Scene = sceneCapture;
  request.SSPMask = method->NeedsSceneColor();
  request.FillBackground = compositingBackground;
  for (int c = 0; c < 3; ++c)
  {
    request.Background[c] = background[c];
    request.Background2[c] = background2[c];
  }
  this->Composited =
    this->GBufferComposite->Composite(renWin, this->Targets, request, exchange);
  this->ReportGLError("the G-buffers' transfer for compositing across ranks");
  return exchange->GetRank() == 0;
}

//------------------------------------------------------------------------------
std::vector<double> vtkRefractionPass::AgreeGlassBounds(
  const std::vector<vtkProp*>& glass, vtkRefractionRankExchange* exchange)
{
  // The glass list is the same on every rank (empty pieces kept), so the calls pair up.
  std::vector<double> bounds(6 * glass.size());
  for (size_t i = 0; i < glass.size(); ++i)
  {
    const double* piece = glass[i]->GetBounds();
    const bool present = piece && piece[0] <= piece[1];
    for (int k = 0; k < 3; ++k)
    {
      bounds[6 * i + 2 * k] = exchange->AllReduceMin(present ? piece[2 * k] : VTK_DOUBLE_MAX);
      bounds[6 * i + 2 * k + 1] =
        exchange->AllReduceMax(present ? piece[2 * k + 1] : -VTK_DOUBLE_MAX);
    }
  }
  return bounds;
}

//------------------------------------------------------------------------------
void vtkRefractionPass::SetRankExchange(vtkRefractionRankExchange* exchange)
{
  if (exchange != this->RankExchange)
  {
    this->RankExchange = exchange;
    this->Modified();
  }
}

vtkRefractionRankExchange* vtkRefractionPass::GetRankExchange()
{
  return this->RankExchange;
}

vtkRefractionRankExchange* vtkRefractionPass::CompositingExchange()
{
  return this->RankExchange && this->RankExchange->GetNumberOfRanks() > 1 ? this->RankExchange
                                                                            : nullptr;
}

double vtkRefractionPass::GetCompositeMilliseconds() const
{
  return this->Composited ? this->GBufferComposite->GetMilliseconds() : 0.0;
}

double vtkRefractionPass::GetCompositeWaitMilliseconds() const
{
  return this->Composited ? this->GBufferComposite->GetWaitMilliseconds() : 0.0;
}

unsigned long long vtkRefractionPass::GetCompositeBufferBytes() const
{
  return this->Composited ? this->GBufferComposite->GetBufferBytes() : 0;
}


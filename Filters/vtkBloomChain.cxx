#include "vtkBloomChain.h"

#include "vtkBloomImageOps.h"
#include "vtkBloomParameters.h"
#include "vtkImagePyramidDown.h"
#include "vtkImagePyramidUp.h"

namespace
{
const int Clamp = vtkBloomLinearOperator::BORDER_CLAMP;

vtkBloomChain::Term Resample(const int in[2], const int out[2],
  const std::vector<vtkBloomKernels::Tap>& taps, double weight = 1.0)
{
  vtkBloomChain::Term term;
  term.Weight = weight;
  term.X = vtkBloomLinearOperator::Resample(in[0], out[0], taps, Clamp);
  term.Y = vtkBloomLinearOperator::Resample(in[1], out[1], taps, Clamp);
  return term;
}

// `passes` applications of one clamped convolution, folded into one operator.
vtkBloomLinearOperator RepeatedConvolution(
  int n, const std::vector<vtkBloomKernels::Tap>& taps, int passes)
{
  const vtkBloomLinearOperator once = vtkBloomLinearOperator::Convolve(n, taps, Clamp);
  vtkBloomLinearOperator result = once;
  for (int it = 1; it < passes; ++it)
  {
    result = once.Compose(result);
  }
  return result;
}
}

//------------------------------------------------------------------------------
void vtkBloomChain::Build(vtkBloomParameters* p, int width, int height)
{
  *this = vtkBloomChain();
  this->Width = width;
  this->Height = height;
  this->AccumulateMode = p->GetAccumulateMode();

  const int full[2] = { width, height };
  const auto sizes = p->ComputeLevelSizes(width, height);
  const auto bilinear = vtkBloomKernels::BilinearTaps();
  const auto up = p->GetUpsampleKernel() == vtkImagePyramidUp::BILINEAR
    ? vtkBloomKernels::BilinearTaps()
    : vtkBloomKernels::TentTaps();
  const auto blurTaps = vtkBloomKernels::SymmetricTaps(
    p->GetEffectiveBlurHalfKernel(height), p->GetEffectiveBlurTapSpacing(height));
  const int iterations = p->GetBlurIterations();

  this->Levels.resize(sizes.size());
  for (size_t i = 0; i < sizes.size(); ++i)
  {
    Level& level = this->Levels[i];
    level.Size[0] = sizes[i].first;
    level.Size[1] = sizes[i].second;
    level.Weight = p->GetEffectiveLevelWeight(static_cast<int>(i), height);
    if (i > 0)
    {
      const int* previous = this->Levels[i - 1].Size;
      level.Karis = p->GetKarisAverage() && i == 1 &&
        p->GetDownsampleKernel() == vtkImagePyramidDown::JIMENEZ13;
      for (auto& t :
        vtkBloomDownsampleTerms(p->GetDownsampleKernel(), level.Karis, previous, level.Size))
      {
        level.Down.push_back(Term{ t.Weight, std::move(t.X), std::move(t.Y) });
      }
    }
    level.Blur = level.Weight != 0.0 && iterations > 0;
    if (level.Blur)
    {
      level.BlurPass.X = RepeatedConvolution(level.Size[0], blurTaps, iterations);
      level.BlurPass.Y = RepeatedConvolution(level.Size[1], blurTaps, iterations);
    }
    if (this->AccumulateMode == vtkBloomParameters::DIRECT && level.Weight != 0.0)
    {
      level.Full = Resample(level.Size, full, bilinear);
    }
  }
  if (this->AccumulateMode != vtkBloomParameters::DIRECT)
  {
    for (size_t i = 0; i + 1 < this->Levels.size(); ++i)
    {
      this->Levels[i].Up = Resample(this->Levels[i + 1].Size, this->Levels[i].Size, up);
    }
  }
  if (!this->Levels.empty())
  {
    this->SourceIsIdentity = p->GetEffectiveStartLevel(height) == 0;
    if (!this->SourceIsIdentity)
    {
      this->Source = Resample(full, this->Levels[0].Size, bilinear);
    }
    this->FinalIsIdentity =
      this->AccumulateMode == vtkBloomParameters::DIRECT || p->GetEffectiveStartLevel(height) == 0;
    if (!this->FinalIsIdentity)
    {
      this->Final = Resample(this->Levels[0].Size, full, bilinear);
    }
  }
}

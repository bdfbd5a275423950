// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkImageSeparableGaussian.h"

#include "vtkBloomPieces.h"

#include "vtkBloomFFTConvolution.h"
#include "vtkBloomImageOps.h"
#include "vtkBloomKernels.h"
#include "vtkBloomLineFilters.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkImageSeparableGaussian);

struct vtkImageSeparableGaussian::FFTAxis
{
  vtkBloomFFTConvolution Convolution;
  vtkBloomLinearOperator Operator;
  std::vector<double> Half; ///< what it was built for
  int Border = -1;
  bool Single = true;
  bool Cheaper = false; ///< FFT cost below the direct cost
};

namespace
{
//------------------------------------------------------------------------------
// Non-finite bookkeeping: bit 0 = +Inf, bit 1 = -Inf, bit 2 = NaN.
enum : std::uint8_t
{
  KIND_POSITIVE_INFINITY = 1,
  KIND_NEGATIVE_INFINITY = 2,
  KIND_NAN = 4
};

std::uint8_t KindOf(double v)
{
  if (std::isnan(v))
  {
    return KIND_NAN;
  }
  if (std::isinf(v))
  {
    return v > 0 ? KIND_POSITIVE_INFINITY : KIND_NEGATIVE_INFINITY;
  }
  return 0;
}

// Kinds of the samples of a block (same indexing as vtkBloomBuffer).
struct KindBlock
{
  int Lo[3] = { 0, 0, 0 };
  int Size[3] = { 0, 0, 0 };
  int NumberOfComponents = 0;
  std::vector<std::uint8_t> Kinds;

  size_t Offset(int i, int j, int k) const
  {
    return ((static_cast<size_t>(k - this->Lo[2]) * this->Size[1] + (j - this->Lo[1])) *
               this->Size[0] +
             (i - this->Lo[0])) *
      this->NumberOfComponents;
  }
};

// out[o] = OR of in[m] over the non-zero taps m of op's row o, for o in [outLo, outLo + outSize).
KindBlock DilateKinds(
  const KindBlock& in, int axis, const vtkBloomLinearOperator& op, int outLo, int outSize)
{
  KindBlock out;
  std::copy(in.Lo, in.Lo + 3, out.Lo);
  std::copy(in.Size, in.Size + 3, out.Size);
  out.Lo[axis] = outLo;
  out.Size[axis] = outSize;
  out.NumberOfComponents = in.NumberOfComponents;
  const int nc = in.NumberOfComponents;
  out.Kinds.assign(
    static_cast<size_t>(out.Size[0]) * out.Size[1] * out.Size[2] * nc, std::uint8_t(0));
  int idx[3];
  for (idx[2] = out.Lo[2]; idx[2] < out.Lo[2] + out.Size[2]; ++idx[2])
  {
    for (idx[1] = out.Lo[1]; idx[1] < out.Lo[1] + out.Size[1]; ++idx[1])
    {
      for (idx[0] = out.Lo[0]; idx[0] < out.Lo[0] + out.Size[0]; ++idx[0])
      {
        std::uint8_t* dst = out.Kinds.data() + out.Offset(idx[0], idx[1], idx[2]);
        const int o = idx[axis];
        for (int t = 0; t < op.Width; ++t)
        {
          const int m = op.First[o] + t;
          if (op.Weights[static_cast<size_t>(o) * op.Width + t] == 0.0 || m < in.Lo[axis] ||
            m >= in.Lo[axis] + in.Size[axis])
          {
            continue;
          }
          int src[3] = { idx[0], idx[1], idx[2] };
          src[axis] = m;
          const std::uint8_t* s = in.Kinds.data() + in.Offset(src[0], src[1], src[2]);
          for (int c = 0; c < nc; ++c)
          {
            dst[c] |= s[c];
          }
        }
      }
    }
  }
  return out;
}

//------------------------------------------------------------------------------
// Replace the non-finite samples of `data` (n values) in place: with sanitize, NaN -> 0 and
// +/-Inf -> the finite extremes of T; otherwise all of them -> 0. Records kinds when asked.
template <typename T>
bool CleanValues(T* data, vtkIdType n, bool sanitize, std::vector<std::uint8_t>* kinds)
{
  bool found = false;
  for (vtkIdType e = 0; e < n; ++e)
  {
    const T v = data[e];
    if (std::isfinite(v))
    {
      continue;
    }
    found = true;
    if (kinds)
    {
      (*kinds)[e] = KindOf(static_cast<double>(v));
    }
    if (sanitize && std::isinf(v))
    {
      data[e] = v > 0 ? std::numeric_limits<T>::max() : std::numeric_limits<T>::lowest();
    }
    else
    {
      data[e] = T(0);
    }
  }
  return found;
}

template <typename T>
bool HasNonFinite(const T* data, vtkIdType n)
{
  for (vtkIdType e = 0; e < n; ++e)
  {
    if (!std::isfinite(data[e]))
    {
      return true;
    }
  }
  return false;
}

// Clamp to the finite range of T (NaN from an overflow becomes 0), over an extent.
template <typename T>
void ClampToFinite(vtkImageData* image, const int extent[6])
{
  const int nc = image->GetNumberOfScalarComponents();
  for (int k = extent[4]; k <= extent[5]; ++k)
  {
    for (int j = extent[2]; j <= extent[3]; ++j)
    {
      T* p = static_cast<T*>(image->GetScalarPointer(extent[0], j, k));
      const size_t count = static_cast<size_t>(extent[1] - extent[0] + 1) * nc;
      for (size_t e = 0; e < count; ++e)
      {
        if (!std::isfinite(p[e]))
        {
          p[e] = std::isnan(p[e])
            ? T(0)
            : (p[e] > 0 ? std::numeric_limits<T>::max() : std::numeric_limits<T>::lowest());
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
// A copy of `input` with its non-finite samples replaced (see CleanValues). Without
// sanitize, `kinds` records which samples were +Inf, -Inf or NaN, indexed from the whole
// extent's origin, so that RequestData can mark the outputs they reach.
vtkSmartPointer<vtkImageData> CleanCopy(
  vtkImageData* input, const int whole[6], bool sanitize, KindBlock& kinds)
{
  vtkSmartPointer<vtkImageData> clean = vtkSmartPointer<vtkImageData>::New();
  clean->DeepCopy(input);
  const vtkIdType count = input->GetPointData()->GetScalars()->GetNumberOfValues();
  void* data = clean->GetPointData()->GetScalars()->GetVoidPointer(0);
  std::vector<std::uint8_t>* record = nullptr;
  if (!sanitize)
  {
    int ext[6];
    input->GetExtent(ext);
    for (int a = 0; a < 3; ++a)
    {
      kinds.Lo[a] = ext[2 * a] - whole[2 * a];
      kinds.Size[a] = ext[2 * a + 1] - ext[2 * a] + 1;
    }
    kinds.NumberOfComponents = input->GetNumberOfScalarComponents();
    kinds.Kinds.assign(static_cast<size_t>(count), std::uint8_t(0));
    record = &kinds.Kinds;
  }
  if (input->GetScalarType() == VTK_FLOAT)
  {
    CleanValues(static_cast<float*>(data), count, sanitize, record);
  }
  else
  {
    CleanValues(static_cast<double*>(data), count, sanitize, record);
  }
  return clean;
}

//------------------------------------------------------------------------------
// Bytes per piece for the EXACT direct path's slabs: every piece repeats the x pass over the
// rows its y support needs, so the default pieces of 64 KiB (a few rows) would redo it about
// 2R / rows times; cut slabs instead, about four per thread.
vtkIdType SlabBytesPerPiece(vtkImageData* input, const int updateExtent[6])
{
  vtkIdType bytes =
    static_cast<vtkIdType>(input->GetNumberOfScalarComponents()) * input->GetScalarSize();
  for (int a = 0; a < 3; ++a)
  {
    bytes *= std::max(updateExtent[2 * a + 1] - updateExtent[2 * a] + 1, 1);
  }
  const int threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  return std::max<vtkIdType>(65536, bytes / (4 * threads));
}

//------------------------------------------------------------------------------
// Write the non-finite value each kind stands for (+Inf, -Inf or NaN) into the outputs of
// `outExt` whose kinds (indexed from the whole extent's origin) are set.
void WriteKinds(
  vtkImageData* output, const int outExt[6], const int whole[6], const KindBlock& kinds)
{
  const int nc = output->GetNumberOfScalarComponents();
  for (int k = outExt[4]; k <= outExt[5]; ++k)
  {
    for (int j = outExt[2]; j <= outExt[3]; ++j)
    {
      for (int i = outExt[0]; i <= outExt[1]; ++i)
      {
        const std::uint8_t* kind =
          kinds.Kinds.data() + kinds.Offset(i - whole[0], j - whole[2], k - whole[4]);
        for (int c = 0; c < nc; ++c)
        {
          if (!kind[c])
          {
            continue;
          }
          const double value = kind[c] == KIND_POSITIVE_INFINITY
            ? std::numeric_limits<double>::infinity()
            : (kind[c] == KIND_NEGATIVE_INFINITY ? -std::numeric_limits<double>::infinity()
                                                 : std::numeric_limits<double>::quiet_NaN());
          output->SetScalarComponentFromDouble(i, j, k, c, value);
        }
      }
    }
  }
}
}

//------------------------------------------------------------------------------
vtkImageSeparableGaussian::vtkImageSeparableGaussian()
{
  this->StandardDeviations[0] = 2.0;
  this->StandardDeviations[1] = 2.0;
  this->StandardDeviations[2] = 0.0;
  this->Radius[0] = this->Radius[1] = this->Radius[2] = -1;
  this->RadiusFactor = 4.0;
  this->KernelType = SAMPLED;
  this->BorderMode = CLAMP;
  this->Method = EXACT;
  this->ConvolutionMode = CONVOLUTION_AUTOMATIC;
  this->LastFFTAxes = 0;
  this->SanitizeNonFinite = true;
  this->CleanInput = nullptr;
}

//------------------------------------------------------------------------------
vtkImageSeparableGaussian::~vtkImageSeparableGaussian() = default;

//------------------------------------------------------------------------------
std::vector<double> vtkImageSeparableGaussian::GetHalfKernel(int axis)
{
  if (axis < 0 || axis > 2)
  {
    return { 1.0 };
  }
  const double sigma = this->StandardDeviations[axis];
  const int radius = this->Radius[axis] >= 0
    ? this->Radius[axis]
    : vtkBloomKernels::RadiusForSigma(sigma, this->RadiusFactor);
  return vtkBloomKernels::GaussianHalfKernel(sigma, radius, this->KernelType);
}

//------------------------------------------------------------------------------
bool vtkImageSeparableGaussian::BuildTerms(
  const int inWhole[6], const int*, std::vector<Term>& terms)
{
  Term term;
  for (int a = 0; a < 3; ++a)
  {
    const double sigma = this->StandardDeviations[a];
    if (!(sigma >= 0.0) || !std::isfinite(sigma))
    {
      vtkErrorMacro(<< "StandardDeviations must be finite and >= 0; axis " << a << " has " << sigma
                    << ".");
      return false;
    }
    const std::vector<double> half = this->GetHalfKernel(a);
    const int n = inWhole[2 * a + 1] - inWhole[2 * a] + 1;
    if (half.size() > 1 && n > 0)
    {
      term.Operators[a] = vtkBloomLinearOperator::Convolve(
        n, vtkBloomKernels::SymmetricTaps(half, 1.0), this->BorderMode);
      term.Use[a] = !term.Operators[a].IsIdentity();
    }
  }
  terms.push_back(std::move(term));
  return true;
}

//------------------------------------------------------------------------------
const char* vtkImageSeparableGaussian::GetMethodName(int method)
{
  switch (method)
  {
    case BOX_CASCADE_3:
      return "BoxCascade3";
    case BOX_CASCADE_5:
      return "BoxCascade5";
    case RECURSIVE:
      return "Recursive";
    default:
      return "Exact";
  }
}

//------------------------------------------------------------------------------
int vtkImageSeparableGaussian::ChooseFFTAxes(const int inWhole[6], int precision)
{
  int axes = 0;
  if (this->Method != EXACT || this->ConvolutionMode == CONVOLUTION_DIRECT)
  {
    return axes;
  }
  for (int a = 0; a < 3; ++a)
  {
    const double sigma = this->StandardDeviations[a];
    const int n = inWhole[2 * a + 1] - inWhole[2 * a] + 1;
    if (!(sigma > 0.0) || !std::isfinite(sigma) || n < 2)
    {
      continue;
    }
    const std::vector<double> half = this->GetHalfKernel(a);
    if (half.size() < 2)
    {
      continue;
    }
    // The choice does not depend on the precision, so a convolution built for the other one
    // answers ANY_PRECISION (RequestUpdateExtent, before the scalar type is known) and is
    // rebuilt only when RequestData needs the other precision.
    std::unique_ptr<FFTAxis>& fft = this->FFT[a];
    const bool single = precision != DOUBLE_PRECISION;
    if (!fft || fft->Half != half || fft->Border != this->BorderMode ||
      (precision != ANY_PRECISION && fft->Single != single) || fft->Operator.InputSize != n)
    {
      fft.reset(new FFTAxis);
      fft->Half = half;
      fft->Border = this->BorderMode;
      fft->Single = single;
      fft->Operator = vtkBloomLinearOperator::Convolve(
        n, vtkBloomKernels::SymmetricTaps(half, 1.0), this->BorderMode);
      fft->Convolution.Build(fft->Operator, this->BorderMode, single);
      fft->Cheaper = fft->Convolution.Cost() < vtkBloomFFTConvolution::DirectCost(fft->Operator);
    }
    if (fft->Convolution.IsReady() && (this->ConvolutionMode == CONVOLUTION_FFT || fft->Cheaper))
    {
      axes |= 1 << a;
    }
  }
  return axes;
}

//------------------------------------------------------------------------------
vtkBloomLinearOperator vtkImageSeparableGaussian::SupportOperator(int axis, int n)
{
  const double sigma = this->StandardDeviations[axis];
  int radius = 0;
  switch (this->Method)
  {
    case BOX_CASCADE_3:
    case BOX_CASCADE_5:
    {
      const int passes = this->Method == BOX_CASCADE_3 ? 3 : 5;
      const auto box = vtkBloomKernels::ExtendedBoxForVariance(sigma * sigma / passes);
      radius = passes * (box.Radius + (box.Alpha > 0.0 ? 1 : 0));
      break;
    }
    case RECURSIVE:
      radius = vtkBloomKernels::RadiusForSigma(sigma, this->RadiusFactor);
      break;
    default:
    {
      const std::vector<double> half = this->GetHalfKernel(axis);
      return vtkBloomLinearOperator::Convolve(
        n, vtkBloomKernels::SymmetricTaps(half, 1.0), this->BorderMode);
    }
  }
  std::vector<double> ones(static_cast<size_t>(std::max(radius, 0)) + 1, 1.0);
  return vtkBloomLinearOperator::Convolve(
    n, vtkBloomKernels::SymmetricTaps(ones, 1.0), this->BorderMode);
}

//------------------------------------------------------------------------------
int vtkImageSeparableGaussian::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int inWhole[6], outExt[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), inWhole);
  if (this->Method == EXACT && this->ChooseFFTAxes(inWhole, ANY_PRECISION) == 0)
  {
    return this->Superclass::RequestUpdateExtent(request, inputVector, outputVector);
  }
  // The fast methods and the FFT read whole lines on every filtered axis.
  vtkBloomExecutionExtent(outInfo, outExt);
  int inExt[6];
  for (int a = 0; a < 3; ++a)
  {
    const bool filtered = this->StandardDeviations[a] > 0.0;
    inExt[2 * a] = filtered ? inWhole[2 * a] : std::max(outExt[2 * a], inWhole[2 * a]);
    inExt[2 * a + 1] =
      filtered ? inWhole[2 * a + 1] : std::min(outExt[2 * a + 1], inWhole[2 * a + 1]);
    if (inExt[2 * a] > inExt[2 * a + 1])
    {
      std::copy(inWhole, inWhole + 6, inExt);
      break;
    }
  }
  vtkBloomRequestExactExtent(inInfo, inExt);
  return 1;
}

//------------------------------------------------------------------------------
int vtkImageSeparableGaussian::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* input = vtkImageData::GetData(inInfo);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  if (!input || !input->GetPointData()->GetScalars() ||
    !vtkImageSeparableAlgorithm::IsSupportedInput(
      input->GetScalarType(), input->GetNumberOfScalarComponents()))
  {
    // The superclass reports the error and empties the output.
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  for (int a = 0; a < 3; ++a)
  {
    const double sigma = this->StandardDeviations[a];
    if (!(sigma >= 0.0) || !std::isfinite(sigma))
    {
      vtkErrorMacro(<< "StandardDeviations must be finite and >= 0; axis " << a << " has " << sigma
                    << ".");
      output->Initialize();
      return 0;
    }
  }

  // Non-finite input: work on a cleaned copy (see the class description).
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  const vtkIdType count = scalars->GetNumberOfValues();
  const bool isFloat = input->GetScalarType() == VTK_FLOAT;
  void* raw = scalars->GetVoidPointer(0);
  const bool nonFinite = isFloat ? HasNonFinite(static_cast<const float*>(raw), count)
                                 : HasNonFinite(static_cast<const double*>(raw), count);
  vtkSmartPointer<vtkImageData> clean;
  KindBlock kinds;
  if (nonFinite)
  {
    clean = CleanCopy(input, inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()),
      this->SanitizeNonFinite, kinds);
    this->CleanInput = clean;
  }

  int result = 1;
  const int* inWhole = inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
  const int fftAxes = this->ChooseFFTAxes(inWhole, isFloat ? SINGLE_PRECISION : DOUBLE_PRECISION);
  this->LastFFTAxes = fftAxes;
  if (this->Method == EXACT && fftAxes == 0)
  {
    // The direct path, threaded by the superclass over slabs.
    int updateExtent[6];
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), updateExtent);
    this->SplitMode = SLAB;
    this->DesiredBytesPerPiece = SlabBytesPerPiece(input, updateExtent);
    result = this->Superclass::RequestData(request, inputVector, outputVector);
  }
  else
  {
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), this->InputWholeExtent);
    outInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), this->OutputWholeExtent);
    int outExt[6];
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), outExt);
    vtkBloomMatchOutputScalars(outInfo, input);
    this->AllocateOutputData(output, outInfo, outExt);
    this->CopyAttributeData(input, output, inputVector);
    this->ExecuteLines(clean ? clean.Get() : input, output, outExt, fftAxes);
  }
  this->CleanInput = nullptr;
  if (!result || !output->GetPointData()->GetScalars())
  {
    return result;
  }

  int outExt[6];
  output->GetExtent(outExt);
  if (this->SanitizeNonFinite)
  {
    if (isFloat)
    {
      ClampToFinite<float>(output, outExt);
    }
    else
    {
      ClampToFinite<double>(output, outExt);
    }
  }
  else if (nonFinite)
  {
    // Mark the outputs whose support holds a non-finite input sample.
    const int* whole = inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
    for (int a = 0; a < 3; ++a)
    {
      if (!(this->StandardDeviations[a] > 0.0))
      {
        continue;
      }
      const int n = whole[2 * a + 1] - whole[2 * a] + 1;
      const vtkBloomLinearOperator op = this->SupportOperator(a, n);
      kinds = DilateKinds(
        kinds, a, op, outExt[2 * a] - whole[2 * a], outExt[2 * a + 1] - outExt[2 * a] + 1);
    }
    WriteKinds(output, outExt, whole, kinds);
  }
  return result;
}

//------------------------------------------------------------------------------
void vtkImageSeparableGaussian::ThreadedRequestData(vtkInformation* request,
  vtkInformationVector** inputVector, vtkInformationVector* outputVector, vtkImageData*** inData,
  vtkImageData** outData, int outExt[6], int threadId)
{
  if (!this->CleanInput)
  {
    this->Superclass::ThreadedRequestData(
      request, inputVector, outputVector, inData, outData, outExt, threadId);
    return;
  }
  vtkImageData* clean[1] = { this->CleanInput };
  vtkImageData** cleanPorts[1] = { clean };
  this->Superclass::ThreadedRequestData(
    request, inputVector, outputVector, cleanPorts, outData, outExt, threadId);
}

//------------------------------------------------------------------------------
void vtkImageSeparableGaussian::ExecuteLines(
  vtkImageData* input, vtkImageData* output, const int outExt[6], int fftAxes)
{
  if (outExt[0] > outExt[1] || outExt[2] > outExt[3] || outExt[4] > outExt[5])
  {
    return;
  }
  const int* whole = this->InputWholeExtent;
  const int wholeLo[3] = { whole[0], whole[2], whole[4] };
  int available[6], ext[6];
  input->GetExtent(available);
  for (int a = 0; a < 3; ++a)
  {
    const bool filtered = this->StandardDeviations[a] > 0.0;
    ext[2 * a] = filtered ? whole[2 * a] : outExt[2 * a];
    ext[2 * a + 1] = filtered ? whole[2 * a + 1] : outExt[2 * a + 1];
    if (ext[2 * a] < available[2 * a] || ext[2 * a + 1] > available[2 * a + 1])
    {
      vtkErrorMacro(<< "The input does not hold the extent the filter needs.");
      return;
    }
  }
  const int nc = input->GetNumberOfScalarComponents();
  vtkBloomBuffer buffer;
  vtkBloomImport(input, ext, wholeLo, 0, nc, buffer);

  int done = 0, total = 0;
  for (int a = 0; a < 3; ++a)
  {
    total += this->StandardDeviations[a] > 0.0 ? 1 : 0;
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    const double sigma = this->StandardDeviations[axis];
    if (!(sigma > 0.0) || this->AbortExecute)
    {
      continue;
    }
    const int n = buffer.Size[axis];
    if (this->Method == EXACT)
    {
      // EXACT on whole lines: through the FFT, or the operator itself on the axes left direct.
      if (fftAxes & (1 << axis))
      {
        this->FFT[axis]->Convolution.ApplyAxis(buffer.Data.data(), buffer.Size, nc, nc, axis);
      }
      else
      {
        const vtkBloomLinearOperator op = this->SupportOperator(axis, n);
        vtkBloomBuffer next;
        vtkBloomApplyAxis(buffer, axis, op, 0, n, next, true);
        buffer = std::move(next);
      }
      this->UpdateProgress(0.95 * (++done) / std::max(total, 1));
      continue;
    }
    // Lines along `axis`: every faster axis and the components are lanes, sample-major.
    size_t stride = static_cast<size_t>(nc);
    for (int b = 0; b < axis; ++b)
    {
      stride *= static_cast<size_t>(buffer.Size[b]);
    }
    size_t groups = 1;
    for (int b = axis + 1; b < 3; ++b)
    {
      groups *= static_cast<size_t>(buffer.Size[b]);
    }
    const size_t chunk = axis == 0 ? stride : std::min<size_t>(stride, 64);
    const size_t chunksPerGroup = (stride + chunk - 1) / chunk;
    const int method = this->Method;
    const int border = this->BorderMode;
    const int passes = method == BOX_CASCADE_5 ? 5 : 3;
    const vtkBloomKernels::ExtendedBox box =
      vtkBloomKernels::ExtendedBoxForVariance(sigma * sigma / passes);
    vtkBloomKernels::RecursiveGaussian recursive;
    vtkBloomLineFilters::Matrix3 periodic{};
    // Below sigma 0.5 the third-order recursion cannot reach the variance: use Lindeberg's
    // discrete kernel (exact variance) directly there.
    const bool direct = method == RECURSIVE && sigma < 0.5;
    const std::vector<double> half = direct
      ? vtkBloomKernels::GaussianHalfKernel(
          sigma, vtkBloomKernels::RadiusForSigma(sigma, 6.0), vtkBloomKernels::GAUSSIAN_DISCRETE)
      : std::vector<double>();
    if (method == RECURSIVE && !direct)
    {
      recursive = vtkBloomKernels::RecursiveGaussianCoefficients(sigma);
      periodic = vtkBloomLineFilters::PeriodicSteadyState(recursive, 2LL * n);
    }
    double* data = buffer.Data.data();
    vtkSMPTools::For(0, static_cast<vtkIdType>(groups * chunksPerGroup),
      [&](vtkIdType begin, vtkIdType end)
      {
        std::vector<double> line, scratch;
        for (vtkIdType u = begin; u < end; ++u)
        {
          const size_t g = static_cast<size_t>(u) / chunksPerGroup;
          const size_t first = (static_cast<size_t>(u) % chunksPerGroup) * chunk;
          const size_t lanes = std::min(chunk, stride - first);
          double* base = data + g * n * stride + first;
          line.resize(static_cast<size_t>(n) * lanes);
          for (int m = 0; m < n; ++m)
          {
            std::copy(base + m * stride, base + m * stride + lanes, line.data() + m * lanes);
          }
          if (direct)
          {
            vtkBloomLineFilters::DirectLine(
              line.data(), n, static_cast<int>(lanes), border, half, scratch);
          }
          else if (method == RECURSIVE)
          {
            vtkBloomLineFilters::RecursiveLine(
              line.data(), n, static_cast<int>(lanes), border, recursive, periodic, scratch);
          }
          else
          {
            vtkBloomLineFilters::BoxCascadeLine(
              line.data(), n, static_cast<int>(lanes), border, box, passes, scratch);
          }
          for (int m = 0; m < n; ++m)
          {
            std::copy(line.data() + m * lanes, line.data() + (m + 1) * lanes, base + m * stride);
          }
        }
      });
    this->UpdateProgress(0.95 * (++done) / std::max(total, 1));
  }
  vtkBloomExport(buffer, wholeLo, output, outExt, 0);
  this->UpdateProgress(1.0);
}

//------------------------------------------------------------------------------
const char* vtkImageSeparableGaussian::GetKernelTypeAsString()
{
  switch (this->KernelType)
  {
    case INTEGRATED:
      return "Integrated";
    case DISCRETE:
      return "Discrete";
    default:
      return "Sampled";
  }
}

//------------------------------------------------------------------------------
const char* vtkImageSeparableGaussian::GetBorderModeAsString()
{
  switch (this->BorderMode)
  {
    case REFLECT:
      return "Reflect";
    case ZERO:
      return "Zero";
    default:
      return "Clamp";
  }
}

//------------------------------------------------------------------------------
void vtkImageSeparableGaussian::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "StandardDeviations: (" << this->StandardDeviations[0] << ", "
     << this->StandardDeviations[1] << ", " << this->StandardDeviations[2] << ")\n";
  os << indent << "Radius: (" << this->Radius[0] << ", " << this->Radius[1] << ", "
     << this->Radius[2] << ")\n";
  os << indent << "RadiusFactor: " << this->RadiusFactor << "\n";
  os << indent << "KernelType: " << this->GetKernelTypeAsString() << "\n";
  os << indent << "BorderMode: " << this->GetBorderModeAsString() << "\n";
  os << indent << "Method: " << this->GetMethodAsString() << "\n";
  os << indent << "ConvolutionMode: " << this->ConvolutionMode << "\n";
  os << indent << "LastFFTAxes: " << this->LastFFTAxes << "\n";
  os << indent << "SanitizeNonFinite: " << (this->SanitizeNonFinite ? "On" : "Off") << "\n";
}

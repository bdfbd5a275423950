// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// Streaming and threading: for every filter, a requested sub-extent (through UpdateExtent, and
// through vtkImageDataStreamer pieces) equals the same region of the whole-image result bit
// for bit, with an upstream vtkImageClip (ClipData on) that hands the filter no more input than
// it asks for; and the result does not depend on the threading (number of threads, SMP on/off,
// split mode, piece size, SMP backend).
#include "vtkBloomReference.h"
#include "vtkBloomTestSupport.h"

#include <vtkExtentTranslator.h>
#include <vtkImageAlgorithm.h>
#include <vtkImageBloom.h>
#include <vtkImageBloomThreshold.h>
#include <vtkImageClip.h>
#include <vtkImageData.h>
#include <vtkImageDataStreamer.h>
#include <vtkImagePyramidDown.h>
#include <vtkImagePyramidUp.h>
#include <vtkImageSeparableGaussian.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkSMPTools.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkThreadedImageAlgorithm.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace
{
struct Case
{
  std::string Name;
  std::function<vtkSmartPointer<vtkImageAlgorithm>()> Make;
  bool TwoInputs = false; // vtkImagePyramidUp: input 0 coarse, input 1 the source image
};

template <typename T>
vtkSmartPointer<vtkImageAlgorithm> As(vtkSmartPointer<T> p)
{
  return vtkSmartPointer<vtkImageAlgorithm>(p.GetPointer());
}

std::vector<Case> Cases()
{
  std::vector<Case> cases;
  for (int mode = 0; mode <= 4; ++mode)
  {
    cases.push_back({ std::string("threshold-") + vtkImageBloomThreshold::GetModeName(mode),
      [mode]()
      {
        auto f = vtkSmartPointer<vtkImageBloomThreshold>::New();
        f->SetMode(mode);
        f->SetThreshold(0.9);
        return As(f);
      } });
  }
  for (int border = 0; border < 3; ++border)
  {
    for (int kind = 0; kind < 3; ++kind)
    {
      cases.push_back({ "gaussian-border" + std::to_string(border) + "-kind" + std::to_string(kind),
        [border, kind]()
        {
          auto f = vtkSmartPointer<vtkImageSeparableGaussian>::New();
          f->SetStandardDeviations(2.5, 1.2, 0.0);
          f->SetBorderMode(border);
          f->SetKernelType(kind);
          return As(f);
        } });
    }
  }
  // A kernel wider than the image, where reflection wraps around several times.
  cases.push_back({ "gaussian-wide-reflect",
    []()
    {
      auto f = vtkSmartPointer<vtkImageSeparableGaussian>::New();
      f->SetStandardDeviations(30.0, 20.0, 0.0);
      f->SetBorderModeToReflect();
      return As(f);
    } });
  // Through the FFT, which reads whole lines and allocates its output itself.
  cases.push_back({ "gaussian-wide-fft",
    []()
    {
      auto f = vtkSmartPointer<vtkImageSeparableGaussian>::New();
      f->SetStandardDeviations(6.0, 5.0, 0.0);
      f->SetConvolutionModeToFFT();
      return As(f);
    } });
  for (int kernel = 0; kernel < 3; ++kernel)
  {
    for (bool karis : { false, true })
    {
      if (karis && kernel != vtkImagePyramidDown::JIMENEZ13)
      {
        continue;
      }
      cases.push_back({ "down-kernel" + std::to_string(kernel) + (karis ? "-karis" : ""),
        [kernel, karis]()
        {
          auto f = vtkSmartPointer<vtkImagePyramidDown>::New();
          f->SetKernel(kernel);
          f->SetKarisAverage(karis);
          return As(f);
        } });
    }
  }
  for (int kernel : { vtkImagePyramidUp::TENT, vtkImagePyramidUp::BILINEAR })
  {
    cases.push_back({ "up-kernel" + std::to_string(kernel),
      [kernel]()
      {
        auto f = vtkSmartPointer<vtkImagePyramidUp>::New();
        f->SetKernel(kernel);
        f->SetFineWeight(0.5);
        return As(f);
      },
      true });
  }
  for (const std::string& preset : vtkImageBloom::GetPresetNames())
  {
    cases.push_back({ "bloom-" + preset,
      [preset]()
      {
        auto f = vtkSmartPointer<vtkImageBloom>::New();
        f->SetPreset(preset.c_str());
        return As(f);
      } });
  }
  // A non-preset chain with the other kernels and modes.
  cases.push_back({ "bloom-custom",
    []()
    {
      auto f = vtkSmartPointer<vtkImageBloom>::New();
      f->SetThresholdMode(vtkImageBloomThreshold::QUADRATIC_KNEE);
      f->SetThreshold(0.7);
      f->SetDownsampleKernel(vtkImagePyramidDown::BINOMIAL);
      f->SetUpsampleKernel(vtkImagePyramidUp::BILINEAR);
      f->SetBlurStandardDeviation(1.5);
      f->SetBlurGaussianKind(2);
      f->SetNumberOfLevels(4);
      f->SetCompositeMode(vtkBloomParameters::LERP);
      return As(f);
    } });
  cases.push_back({ "bloom-karis-direct",
    []()
    {
      auto f = vtkSmartPointer<vtkImageBloom>::New();
      f->SetKarisAverage(true);
      f->SetAccumulateMode(vtkBloomParameters::DIRECT);
      f->SetStartLevel(0);
      f->SetThreshold(0.5);
      return As(f);
    } });
  return cases;
}

// The test data: a 37 x 29 scene with a non-zero extent, and its half-size coarse level.
struct Inputs
{
  vtkSmartPointer<vtkImageData> Image;
  vtkSmartPointer<vtkImageData> Coarse;
};

Inputs MakeInputs(int type)
{
  Inputs in;
  const int lo[2] = { -3, 5 };
  in.Image = vtkBloomRef::ToImage(vtkBloomRef::SyntheticScene(37, 29, 21), 4, type, lo);
  in.Image->SetOrigin(0.5, -2.0, 0.0);
  in.Image->SetSpacing(0.75, 1.5, 1.0);
  const int clo[2] = { 2, -1 };
  in.Coarse = vtkBloomRef::ToImage(vtkBloomRef::RandomImage(18, 14, 4, 0.0, 3.0), 4, type, clo);
  return in;
}

// vtkImageClip that, like ParaView's Wavelet and the XML image readers, says it can produce
// sub-extents, so that its executive splits a request for several pieces into its own piece.
class PieceClip : public vtkImageClip
{
public:
  static PieceClip* New();
  vtkTypeMacro(PieceClip, vtkImageClip);

protected:
  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override
  {
    const int ok = this->Superclass::RequestInformation(request, inputVector, outputVector);
    outputVector->GetInformationObject(0)->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
    return ok;
  }
};
vtkStandardNewMacro(PieceClip);

// A fresh pipeline: clip(ClipData on) -> filter (-> its output port), returned with the clips
// so they stay alive.
struct Pipeline
{
  vtkSmartPointer<vtkImageAlgorithm> Filter;
  vtkNew<PieceClip> Clip0;
  vtkNew<PieceClip> Clip1;
};

void Build(Pipeline& p, const Case& c, const Inputs& in)
{
  p.Filter = c.Make();
  p.Clip0->ClipDataOn();
  p.Clip1->ClipDataOn();
  if (c.TwoInputs)
  {
    p.Clip0->SetInputData(in.Coarse);
    p.Clip1->SetInputData(in.Image);
    p.Filter->SetInputConnection(0, p.Clip0->GetOutputPort());
    p.Filter->SetInputConnection(1, p.Clip1->GetOutputPort());
  }
  else
  {
    p.Clip0->SetInputData(in.Image);
    p.Filter->SetInputConnection(p.Clip0->GetOutputPort());
  }
}

vtkSmartPointer<vtkImageData> Whole(
  const Case& c, const Inputs& in, const std::function<void(vtkImageAlgorithm*)>& tweak = nullptr)
{
  Pipeline p;
  Build(p, c, in);
  if (tweak)
  {
    tweak(p.Filter);
  }
  p.Filter->Update();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->DeepCopy(p.Filter->GetOutputDataObject(0));
  return out;
}

// True when `piece` holds, over `ext`, exactly the bytes `whole` holds there.
bool RegionIdentical(vtkImageData* piece, vtkImageData* whole, const int ext[6], std::string& why)
{
  int pe[6];
  piece->GetExtent(pe);
  for (int a = 0; a < 3; ++a)
  {
    if (pe[2 * a] > ext[2 * a] || pe[2 * a + 1] < ext[2 * a + 1])
    {
      why = "the piece does not cover the requested extent";
      return false;
    }
  }
  if (piece->GetScalarType() != whole->GetScalarType() ||
    piece->GetNumberOfScalarComponents() != whole->GetNumberOfScalarComponents())
  {
    why = "scalar type or components differ";
    return false;
  }
  const size_t bytes = static_cast<size_t>(piece->GetScalarSize()) *
    piece->GetNumberOfScalarComponents() * (ext[1] - ext[0] + 1);
  for (int k = ext[4]; k <= ext[5]; ++k)
  {
    for (int j = ext[2]; j <= ext[3]; ++j)
    {
      if (std::memcmp(piece->GetScalarPointer(ext[0], j, k), whole->GetScalarPointer(ext[0], j, k),
            bytes) != 0)
      {
        why = "values differ in row " + std::to_string(j);
        return false;
      }
    }
  }
  return true;
}

// Sub-extents of a whole extent: interior blocks, single rows and columns, corners, a pixel.
std::vector<std::array<int, 6>> Pieces(const int w[6])
{
  auto clampExt = [&](std::array<int, 6> e)
  {
    for (int a = 0; a < 3; ++a)
    {
      e[2 * a] = std::max(w[2 * a], std::min(e[2 * a], w[2 * a + 1]));
      e[2 * a + 1] = std::max(e[2 * a], std::min(e[2 * a + 1], w[2 * a + 1]));
    }
    return e;
  };
  const int mx = (w[0] + w[1]) / 2, my = (w[2] + w[3]) / 2;
  return { clampExt({ mx - 2, mx + 3, my - 1, my + 2, w[4], w[5] }),
    clampExt({ w[0], w[1], my, my, w[4], w[5] }), clampExt({ mx, mx, w[2], w[3], w[4], w[5] }),
    clampExt({ w[0], w[0] + 4, w[2], w[2] + 3, w[4], w[5] }),
    clampExt({ w[1] - 3, w[1], w[3] - 5, w[3], w[4], w[5] }),
    clampExt({ w[1], w[1], w[2], w[2], w[4], w[5] }),
    clampExt({ w[0] + 1, w[1] - 1, w[2] + 1, w[3] - 1, w[4], w[5] }) };
}

class FiltersStreaming : public ::testing::TestWithParam<int>
{
};
}

// Each requested sub-extent, computed by a fresh pipeline whose upstream clip delivers only the
// input extent the filter asks for, equals the whole result's region bit for bit.
TEST_P(FiltersStreaming, UpdateExtentPiecesMatchWhole)
{
  const Inputs in = MakeInputs(GetParam());
  for (const Case& c : Cases())
  {
    auto whole = Whole(c, in);
    ASSERT_GT(whole->GetNumberOfPoints(), 0) << c.Name;
    int w[6];
    whole->GetExtent(w);
    bool first = true;
    for (const auto& piece : Pieces(w))
    {
      Pipeline p;
      Build(p, c, in);
      ASSERT_TRUE(p.Filter->UpdateExtent(piece.data())) << c.Name;
      vtkImageData* out = vtkImageData::SafeDownCast(p.Filter->GetOutputDataObject(0));
      // The piece really was computed on its own: the output holds just the piece, and for the
      // local filters the upstream clip delivered less than the whole input.
      int got[6];
      out->GetExtent(got);
      EXPECT_TRUE(std::equal(got, got + 6, piece.data())) << c.Name;
      if (first && c.Name.rfind("bloom", 0) != 0 && c.Name.find("wide") == std::string::npos)
      {
        EXPECT_LT(p.Clip0->GetOutput()->GetNumberOfPoints(),
          vtkImageData::SafeDownCast(c.TwoInputs ? in.Coarse : in.Image)->GetNumberOfPoints())
          << c.Name;
      }
      first = false;
      std::string why;
      EXPECT_TRUE(RegionIdentical(out, whole, piece.data(), why))
        << c.Name << " piece [" << piece[0] << ", " << piece[1] << "] x [" << piece[2] << ", "
        << piece[3] << "]: " << why;
    }
  }
}

// Requests by piece, as every rank makes them under MPI (ParaView's pvbatch): the output of
// piece p of N covers the block vtkExtentTranslator gives and equals the whole result there bit
// for bit. The executive keeps UPDATE_EXTENT as the extent of all pieces and splits it only when
// an algorithm executes, so a filter must grow its own piece and ask the input for that extent
// as one piece: otherwise the upstream clip splits the request again and hands over a piece
// without the kernel's support.
TEST_P(FiltersStreaming, PieceRequestsMatchWhole)
{
  const Inputs in = MakeInputs(GetParam());
  for (const Case& c : Cases())
  {
    auto whole = Whole(c, in);
    int w[6];
    whole->GetExtent(w);
    for (int pieces : { 2, 3, 4 })
    {
      for (int piece = 0; piece < pieces; ++piece)
      {
        Pipeline p;
        Build(p, c, in);
        ASSERT_TRUE(p.Filter->UpdatePiece(piece, pieces, 0)) << c.Name;
        vtkImageData* out = vtkImageData::SafeDownCast(p.Filter->GetOutputDataObject(0));
        int expected[6];
        vtkNew<vtkExtentTranslator> translator;
        translator->PieceToExtentThreadSafe(
          piece, pieces, 0, w, expected, vtkExtentTranslator::BLOCK_MODE, 0);
        std::string why;
        EXPECT_TRUE(RegionIdentical(out, whole, expected, why))
          << c.Name << " piece " << piece << " of " << pieces << ": " << why;
      }
    }
  }
}

namespace
{
// A source whose information pass advertises one float component while its data holds the
// 4-component image: what a filter sees when ParaView's array selection hands it another
// array than the one its source advertised.
class MisadvertisingSource : public vtkImageAlgorithm
{
public:
  static MisadvertisingSource* New();
  vtkTypeMacro(MisadvertisingSource, vtkImageAlgorithm);
  vtkSmartPointer<vtkImageData> Image;

protected:
  MisadvertisingSource() { this->SetNumberOfInputPorts(0); }
  int RequestInformation(
    vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkInformation* info = out->GetInformationObject(0);
    info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), this->Image->GetExtent(), 6);
    info->Set(vtkDataObject::ORIGIN(), this->Image->GetOrigin(), 3);
    info->Set(vtkDataObject::SPACING(), this->Image->GetSpacing(), 3);
    vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_FLOAT, 1);
    return 1;
  }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkImageData::GetData(out)->ShallowCopy(this->Image);
    return 1;
  }
};
vtkStandardNewMacro(MisadvertisingSource);
}

// Every filter allocates its output for the scalars that arrive, not for the ones advertised
// (which would overrun the output: caught by the sanitizer leg), and computes what it computes
// from the image given directly.
TEST_P(FiltersStreaming, OutputFollowsTheScalarsThatArrive)
{
  const Inputs in = MakeInputs(GetParam());
  for (const Case& c : Cases())
  {
    if (c.TwoInputs)
    {
      continue;
    }
    auto whole = Whole(c, in);
    vtkNew<MisadvertisingSource> source;
    source->Image = in.Image;
    auto filter = c.Make();
    filter->SetInputConnection(source->GetOutputPort());
    filter->Update();
    EXPECT_TRUE(
      vtkBloomTest::BitIdentical(vtkImageData::SafeDownCast(filter->GetOutputDataObject(0)), whole))
      << c.Name;
  }
}

// vtkImageDataStreamer with 2, 3, 7 and 16 divisions assembles exactly the whole result.
TEST_P(FiltersStreaming, StreamerMatchesWhole)
{
  const Inputs in = MakeInputs(GetParam());
  for (const Case& c : Cases())
  {
    auto whole = Whole(c, in);
    for (int divisions : { 2, 3, 7, 16 })
    {
      Pipeline p;
      Build(p, c, in);
      vtkNew<vtkImageDataStreamer> streamer;
      streamer->SetInputConnection(p.Filter->GetOutputPort());
      streamer->SetNumberOfStreamDivisions(divisions);
      streamer->Update();
      EXPECT_TRUE(vtkBloomTest::BitIdentical(streamer->GetOutput(), whole))
        << c.Name << " with " << divisions << " divisions";
    }
  }
}

// The threaded filters give the same bits with 1 or several threads, with or without SMP, in
// every split mode and with tiny pieces.
TEST_P(FiltersStreaming, ThreadingDoesNotChangeResults)
{
  const Inputs in = MakeInputs(GetParam());
  const std::vector<std::pair<std::string, std::function<void(vtkThreadedImageAlgorithm*)>>>
    settings = {
      { "1 thread, no SMP",
        [](vtkThreadedImageAlgorithm* f)
        {
          f->SetEnableSMP(false);
          f->SetNumberOfThreads(1);
        } },
      { "3 threads, no SMP",
        [](vtkThreadedImageAlgorithm* f)
        {
          f->SetEnableSMP(false);
          f->SetNumberOfThreads(3);
        } },
      { "SMP, blocks of 256 bytes",
        [](vtkThreadedImageAlgorithm* f)
        {
          f->SetEnableSMP(true);
          f->SetSplitModeToBlock();
          f->SetDesiredBytesPerPiece(256);
          f->SetMinimumPieceSize(1, 1, 1);
        } },
      { "SMP, beams",
        [](vtkThreadedImageAlgorithm* f)
        {
          f->SetEnableSMP(true);
          f->SetSplitModeToBeam();
          f->SetDesiredBytesPerPiece(512);
          f->SetMinimumPieceSize(1, 1, 1);
        } },
      { "no SMP, 5 threads, blocks",
        [](vtkThreadedImageAlgorithm* f)
        {
          f->SetEnableSMP(false);
          f->SetNumberOfThreads(5);
          f->SetSplitModeToBlock();
        } },
    };
  for (const Case& c : Cases())
  {
    if (!vtkThreadedImageAlgorithm::SafeDownCast(c.Make()))
    {
      continue;
    }
    auto reference = Whole(c, in);
    for (const auto& s : settings)
    {
      auto out = Whole(
        c, in, [&](vtkImageAlgorithm* f) { s.second(vtkThreadedImageAlgorithm::SafeDownCast(f)); });
      EXPECT_TRUE(vtkBloomTest::BitIdentical(out, reference)) << c.Name << ": " << s.first;
    }
  }
}

// vtkImageBloom runs on vtkSMPTools: the Sequential, STDThread and TBB backends (those
// available) and thread counts give the same bits.
TEST_P(FiltersStreaming, SMPBackendDoesNotChangeResults)
{
  const Inputs in = MakeInputs(GetParam());
  const std::string original = vtkSMPTools::GetBackend();
  for (const Case& c : Cases())
  {
    if (c.Name.rfind("bloom", 0) != 0 && c.Name.rfind("down", 0) != 0)
    {
      continue;
    }
    auto reference = Whole(c, in);
    for (const char* backend : { "Sequential", "STDThread", "TBB" })
    {
      if (!vtkSMPTools::SetBackend(backend))
      {
        continue;
      }
      for (int threads : { 4, 2, 1 })
      {
        vtkSMPTools::Initialize(threads);
        auto out = Whole(c, in);
        EXPECT_TRUE(vtkBloomTest::BitIdentical(out, reference))
          << c.Name << ": backend " << backend << ", " << threads << " threads";
      }
    }
    vtkSMPTools::SetBackend(original.c_str());
    vtkSMPTools::Initialize(0);
  }
}

INSTANTIATE_TEST_SUITE_P(Filters, FiltersStreaming, ::testing::Values(VTK_DOUBLE, VTK_FLOAT),
  [](const ::testing::TestParamInfo<int>& info)
  { return std::string(info.param == VTK_DOUBLE ? "double" : "float"); });

// A 3-D image streamed in z: the Gaussian with sigma_z > 0 and the pyramid filters slice by
// slice give identical bits piece by piece.
TEST(FiltersStreaming3D, ZPiecesMatchWhole)
{
  const int ext[6] = { 0, 10, -2, 6, 3, 14 };
  auto volume = vtkBloomTest::MakeImage(ext, 2, VTK_DOUBLE,
    [](int i, int j, int k, int c)
    { return 10.0 * vtkBloomRef::HashUniform(c, ((k * 16 + j) * 16 + i)); });
  Inputs in;
  in.Image = volume;
  std::vector<Case> cases;
  for (int border = 0; border < 3; ++border)
  {
    cases.push_back({ "gaussian3d-" + std::to_string(border),
      [border]()
      {
        auto f = vtkSmartPointer<vtkImageSeparableGaussian>::New();
        f->SetStandardDeviations(1.0, 0.0, 2.0);
        f->SetBorderMode(border);
        return As(f);
      } });
  }
  cases.push_back({ "down3d", []() { return As(vtkSmartPointer<vtkImagePyramidDown>::New()); } });
  for (const Case& c : cases)
  {
    auto whole = Whole(c, in);
    int w[6];
    whole->GetExtent(w);
    const int zs[][2] = { { w[4], w[4] }, { w[4] + 3, w[4] + 5 }, { w[5], w[5] } };
    for (const auto& z : zs)
    {
      int piece[6] = { w[0], w[1], w[2] + 1, w[3], z[0], z[1] };
      Pipeline p;
      Build(p, c, in);
      p.Filter->UpdateExtent(piece);
      std::string why;
      EXPECT_TRUE(RegionIdentical(
        vtkImageData::SafeDownCast(p.Filter->GetOutputDataObject(0)), whole, piece, why))
        << c.Name << " z [" << z[0] << ", " << z[1] << "]: " << why;
    }
    vtkNew<vtkImageDataStreamer> streamer;
    Pipeline p;
    Build(p, c, in);
    streamer->SetInputConnection(p.Filter->GetOutputPort());
    streamer->SetNumberOfStreamDivisions(5);
    streamer->Update();
    EXPECT_TRUE(vtkBloomTest::BitIdentical(streamer->GetOutput(), whole)) << c.Name;
  }
}

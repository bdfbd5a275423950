// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassPSFSplit.h
 * @brief  (private to vtkBloomPass) the split PSF's convolution on the GPU (vtkBloomParameters'
 *         PSFTailScale > 1), as vtkImageBloom runs it on the CPU: a full-resolution core and a
 *         tail on a grid `scale` times coarser (vtkBloomPSFSplit says how a PSF is split).
 *
 * Per convolution: the bright pass spread onto the grid (SPLIT_DOWN_X, SPLIT_DOWN_Y), the tail's
 * convolution there by the FFT (a vtkBloomPassFFT of its own, six dispatches on a grid about
 * scale^2 times smaller than the exact path's), then one dispatch that convolves the core directly
 * (shared memory, one column of outputs an invocation) and adds the tail interpolated bilinearly
 * (SPLIT_CORE); glsl/vtkBloomPassPSFSplitCS.glsl. The core's cost grows as its area, (2 rc + 1)^2
 * multiply-adds a pixel and channel; cores wider than MaximumCoreRadius are refused.
 */

#ifndef vtkBloomPassPSFSplit_h
#define vtkBloomPassPSFSplit_h

#include "vtkBloomPSFSplit.h" // For the split kernels
#include "vtkBloomPassFFT.h"  // For the tail's convolution
#include "vtkSmartPointer.h"  // For the grid's textures

#include <map>
#include <string>

class vtkBloomPassProfiler;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkBloomPassPSFSplit
{
public:
  vtkBloomPassPSFSplit();
  ~vtkBloomPassPSFSplit();
  vtkBloomPassPSFSplit(const vtkBloomPassPSFSplit&) = delete;
  vtkBloomPassPSFSplit& operator=(const vtkBloomPassPSFSplit&) = delete;

  /// The widest core the pass convolves (its shared rows hold 256 + 2 rc samples a channel).
  static constexpr int MaximumCoreRadius = 256;

  /// Use the split kernels of red, green and blue (one scale) from now on, as `version`.
  void SetKernels(const vtkBloomPSFSplit splits[3], vtkMTimeType version);

  /// Make the grid's textures, the programs and the tail's FFT for width x height images; false,
  /// with the reason in `why`, as vtkBloomPassFFT::Prepare, or for a core wider than the maximum.
  bool Prepare(vtkOpenGLRenderWindow* context, int width, int height, std::string& why);

  /// target = `source` convolved with the split kernels (REFLECT or ZERO borders); its stages
  /// spans of `profiler` sized as the tail's grid, as vtkBloomPassFFT::Convolve's.
  void Convolve(vtkTextureObject* source, vtkTextureObject* target, bool reflect,
    vtkBloomPassProfiler& profiler);

  /// The tail's FFT grid of the last Prepare.
  const int* GetGridSize() const { return this->TailFFT.GetGridSize(); }

  void ReleaseGraphicsResources(vtkWindow* w);

private:
  /// The compute program of `defines`, made on first use; 0 when it does not build (the
  /// reason in `why`, when given).
  unsigned int Program(const std::string& defines, std::string* why = nullptr);
  std::string CoreDefines(bool reflect) const;
  int Uniform(unsigned int program, const char* name);
  /// The uniforms every stage reads: the image's size, the grid's and the scale.
  void SetGrid(unsigned int program);
  /// The bright pass spread onto the grid (CoarseBright).
  void Down(vtkTextureObject* source);
  /// target = the core's direct convolution of `source` plus CoarseBloom interpolated.
  void Core(vtkTextureObject* source, vtkTextureObject* target, bool reflect);
  /// The cores into CoreBuffer, each centred in the widest one's window.
  void UploadCores();
  /// vtkBloomPSFSplit::TentWeights of every column and row into TentBuffer.
  void UploadTents();
  void ReleaseTextures();

  vtkOpenGLRenderWindow* Context = nullptr;
  vtkBloomPSFSplit Splits[3];
  int Scale = 1;
  int CoreRadius = 0;
  vtkMTimeType KernelsVersion = 0;
  vtkMTimeType CoresVersion = 0; ///< the version CoreBuffer holds; 0: none
  int Size[2] = { 0, 0 };
  int CoarseSize[2] = { 0, 0 };
  vtkBloomPassFFT TailFFT;
  vtkSmartPointer<vtkTextureObject> CoarseRows;   ///< the spread along x: nodes x pixel rows
  vtkSmartPointer<vtkTextureObject> CoarseBright; ///< the bright pass on the grid
  vtkSmartPointer<vtkTextureObject> CoarseBloom;  ///< the tail's convolution there
  unsigned int CoreBuffer = 0;
  unsigned int TentBuffer = 0; ///< (j0, j1, t, 0) per column, then per row
  int TentsScale = 0;          ///< the scale TentBuffer was made for
  unsigned int DownPrograms[2] = { 0, 0 };
  unsigned int CorePrograms[2] = { 0, 0 };      ///< zero borders, reflect
  int ProgramsRadius = -1;                      ///< the core radius they were found for
  std::map<std::string, unsigned int> Programs; ///< by #defines; 0: did not build
  std::string BuildLog;                         ///< the last failed build's log
  vtkBloomPassFFT::UniformCache Locations;
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassPSFSplit.h

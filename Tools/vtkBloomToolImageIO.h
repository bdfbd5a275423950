// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtk-bloom command-line tool: reading an EXR input and writing the EXR or PNG output.
#ifndef vtkBloomToolImageIO_h
#define vtkBloomToolImageIO_h

#include "vtkBloomToolSupport.h"

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include <string>

namespace vtkBloomTool
{
/// The default of --max-pixels: 2^28 pixels (16384 x 16384), vtkOpenEXRReader's own default.
constexpr vtkTypeUInt64 DefaultMaximumPixels = vtkTypeUInt64(1) << 28;

/// The image and the display window it came with, which the EXR output keeps.
struct InputImage
{
  vtkSmartPointer<vtkImageData> Image;
  int DisplayWindow[4] = { 0, -1, 0, -1 };
};

/// Read an EXR file, refusing images above `maximumPixels` (and their decoded bytes) before
/// anything is allocated. Throws RunError.
InputImage ReadInput(const std::string& path, vtkTypeUInt64 maximumPixels, ErrorCollector& errors,
  ProgressBar& progress);

/// The image as float RGBA: the image itself when it already is (no copy), else a converted
/// copy (alpha 1 when absent, grey replicated for 1 and 2 components).
vtkSmartPointer<vtkImageData> AsFloatRGBA(vtkImageData* image);

/// Display encoding for PNG: exposure, the ACES filmic fit of Narkowicz (2015), sRGB OETF.
unsigned char ToneMap(double linear, double exposure);

/// Write bytes to a temporary file beside `path`, then rename it over `path`, so a failure
/// never leaves a partial file and never clobbers an existing one.
void WriteFileAtomically(const std::string& path, const unsigned char* data, size_t size);

/// Write `image` (1 to 4 components) as float32 RGBA .exr, or tone-mapped to opaque 8-bit
/// RGB .png, by the extension of `path`. Throws RunError.
void WriteOutput(vtkImageData* image, const int displayWindow[4], const std::string& path,
  double exposure, ErrorCollector& errors, ProgressBar& progress);
}

#endif

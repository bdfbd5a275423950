// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkOpenEXRDecode.h
 * @brief  (private to vtkOpenEXRReader) pixel decoding: chunks decompressed by the OpenEXR core
 *         library on several threads and unpacked into the interleaved output, and the
 *         luminance/chroma conversion.
 *
 * Both run only on a header and a chunk table that vtkOpenEXRHeader.h has validated.
 */
#ifndef vtkOpenEXRDecode_h
#define vtkOpenEXRDecode_h

#include "vtkOpenEXRHeader.h"

#include <string>
#include <vector>

class vtkAlgorithm;

/**
 * Decode every chunk of `chunks` into `output` (width * height * components floats, or
 * unsigned ints when `unsignedOutput`). Chunks are decoded in parallel with vtkSMPTools, one
 * decompression buffer per thread. With `output` null the chunks are only decompressed and
 * their layout checked, which validates luminance/chroma files before the C++ library reads
 * them. Progress and AbortExecute go through `progress` (on the calling thread).
 */
bool vtkOpenEXRDecodeChunks(vtkOpenEXRCoreFile& file, const vtkOpenEXRHeader& header,
  const std::vector<vtkOpenEXRChunk>& chunks, void* output, bool unsignedOutput,
  vtkAlgorithm* progress, vtkOpenEXRFailure& failure);

/**
 * Luminance/chroma: Imf::RgbaInputFile reconstructs the subsampled chroma and converts to RGB.
 */
bool vtkOpenEXRConvertLuminanceChroma(const std::string& fileName, const vtkOpenEXRHeader& header,
  float* output, vtkOpenEXRFailure& failure);

/**
 * DWAA and DWAB: OpenEXR 3.1's core library does not implement their decompression, so parts
 * compressed with them are read by the C++ library (Imf::InputPart, on OpenEXR's thread pool),
 * after vtkOpenEXRReadChunkTable() has validated the chunk table and the expansion bound.
 */
bool vtkOpenEXRDecodeWithImf(const std::string& fileName, const vtkOpenEXRHeader& header,
  void* output, bool unsignedOutput, vtkOpenEXRFailure& failure);

#endif
// VTK-HeaderTest-Exclude: vtkOpenEXRDecode.h

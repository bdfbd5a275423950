// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkOpenEXRHeader.h
 * @brief  (private to vtkOpenEXRReader) header validation and the limits that bound what a
 *         file can make the reader allocate.
 *
 * Everything here runs before any pixel memory is allocated:
 * - ReadHeader() parses the selected part (storage, windows, channels), chooses the channels
 *   that become output components, and refuses images above the pixel and byte limits.
 * - ReadChunkTable() visits every chunk of level 0, checks that it lies where the data window
 *   puts it and inside the file, and that its compressed bytes can decode to the size the
 *   header claims: no compression expands data by more than MaximumExpansion() (deflate, the
 *   strongest stage, by at most 1032:1). A header that claims a huge image but is backed by a
 *   few hundred bytes is refused here, in time and memory bounded by the file's size.
 */
#ifndef vtkOpenEXRHeader_h
#define vtkOpenEXRHeader_h

#include "vtkOpenEXRCoreFile.h"

#include <string>
#include <vector>

//------------------------------------------------------------------------------
// One channel of the selected part, with its name split at the last '.' into layer and base.
struct vtkOpenEXRChannel
{
  std::string Name;
  std::string Layer;
  std::string Base;
  exr_pixel_type_t Type = EXR_PIXEL_HALF;
  int XSampling = 1;
  int YSampling = 1;
};

//------------------------------------------------------------------------------
// What the reader agrees to allocate for one image.
struct vtkOpenEXRLimits
{
  vtkTypeUInt64 MaximumImageBytes = 0;
  vtkTypeUInt64 MaximumImagePixels = 0;
};

//------------------------------------------------------------------------------
// What the header says about the selected part, and how it maps to the output.
struct vtkOpenEXRHeader
{
  std::vector<std::string> PartNames;
  int Part = -1;
  exr_storage_t Storage = EXR_STORAGE_SCANLINE;
  exr_compression_t Compression = EXR_COMPRESSION_NONE;
  int DataWindow[4] = { 0, -1, 0, -1 };
  int DisplayWindow[4] = { 0, -1, 0, -1 };
  vtkTypeInt64 Width = 0;
  vtkTypeInt64 Height = 0;
  std::vector<vtkOpenEXRChannel> Channels;
  std::string Layer;
  // Luminance/chroma data is decoded by the core library only to validate it, then converted
  // by Imf::RgbaInputFile; everything else is decoded straight into the output.
  bool LuminanceChroma = false;
  // Channel (index into Channels) decoded into each output component; for luminance/chroma,
  // the channels that are validated (Y, RY, BY, A).
  std::vector<int> Decoded;
  std::vector<std::string> ComponentNames;
  int ScalarType = 0; // VTK_FLOAT or VTK_UNSIGNED_INT once read
  int NumberOfComponents = 0;

  bool SameLayout(const vtkOpenEXRHeader& other) const;
};

//------------------------------------------------------------------------------
// One chunk of level 0, validated: where it is in the file and which pixels it holds.
struct vtkOpenEXRChunk
{
  exr_chunk_info_t Info;
  int32_t StartX = 0;
  int32_t StartY = 0;

  /**
   * The chunk for an error message: its codec, its pixels and its sizes, e.g. "the ZIP chunk
   * of pixels (0, 16) to (96, 31), 2710 bytes for 12416".
   */
  std::string Describe() const;
};

/**
 * Parse and validate everything the reader needs from the header of the selected part (by
 * name when partName is not empty, else by index).
 */
bool vtkOpenEXRReadHeader(vtkOpenEXRCoreFile& file, int partIndex, const std::string& partName,
  const std::string& layer, const vtkOpenEXRLimits& limits, vtkOpenEXRHeader& header,
  vtkOpenEXRFailure& failure);

/**
 * The most bytes that `compression` can decode from one compressed byte, for the formats as
 * OpenEXR 3.1 writes them (see the implementation for the derivation of each bound).
 */
vtkTypeUInt64 vtkOpenEXRMaximumExpansion(exr_compression_t compression);

/**
 * Validate the whole chunk table of level 0 of the selected part and return it in order.
 */
bool vtkOpenEXRReadChunkTable(vtkOpenEXRCoreFile& file, const vtkOpenEXRHeader& header,
  const vtkOpenEXRLimits& limits, std::vector<vtkOpenEXRChunk>& chunks, vtkOpenEXRFailure& failure);

#endif
// VTK-HeaderTest-Exclude: vtkOpenEXRHeader.h

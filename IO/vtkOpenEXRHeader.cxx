// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenEXRHeader.h"

#include "vtkErrorCode.h"
#include "vtkType.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <sstream>

namespace
{
//------------------------------------------------------------------------------
// a * b, or false when the product does not fit in 64 bits.
bool CheckedMultiply(vtkTypeUInt64 a, vtkTypeUInt64 b, vtkTypeUInt64& product)
{
  if (a != 0 && b > std::numeric_limits<vtkTypeUInt64>::max() / a)
  {
    return false;
  }
  product = a * b;
  return true;
}

//------------------------------------------------------------------------------
std::string JoinNames(const std::vector<std::string>& names)
{
  std::string joined;
  for (const std::string& name : names)
  {
    joined += (joined.empty() ? "'" : ", '") + name + "'";
  }
  return joined.empty() ? std::string("(none)") : joined;
}

//------------------------------------------------------------------------------
const char* StorageName(exr_storage_t storage)
{
  switch (storage)
  {
    case EXR_STORAGE_SCANLINE:
      return "scanlineimage";
    case EXR_STORAGE_TILED:
      return "tiledimage";
    case EXR_STORAGE_DEEP_SCANLINE:
      return "deepscanline";
    case EXR_STORAGE_DEEP_TILED:
      return "deeptile";
    default:
      return "unknown";
  }
}

//------------------------------------------------------------------------------
// Read a box attribute and check that its size is representable as a VTK extent.
bool ReadWindow(
  vtkOpenEXRCoreFile& file, int part, bool data, int window[4], vtkOpenEXRFailure& failure)
{
  exr_attr_box2i_t box;
  const exr_result_t result = data ? exr_get_data_window(file.Context, part, &box)
                                   : exr_get_display_window(file.Context, part, &box);
  const char* what = data ? "data window" : "display window";
  if (result != EXR_ERR_SUCCESS)
  {
    return failure.Set(vtkErrorCode::FileFormatError,
      std::string("cannot read the ") + what + ": " + file.Describe(result));
  }
  const vtkTypeInt64 width = static_cast<vtkTypeInt64>(box.max.x) - box.min.x + 1;
  const vtkTypeInt64 height = static_cast<vtkTypeInt64>(box.max.y) - box.min.y + 1;
  // VTK computes dimensions as int, so each side must stay below 2^31.
  if (width < 1 || height < 1 || width > VTK_INT_MAX || height > VTK_INT_MAX)
  {
    std::ostringstream message;
    message << "invalid " << what << " (" << box.min.x << ", " << box.min.y << ") - (" << box.max.x
            << ", " << box.max.y << ")";
    return failure.Set(vtkErrorCode::FileFormatError, message.str());
  }
  window[0] = box.min.x;
  window[1] = box.max.x;
  window[2] = box.min.y;
  window[3] = box.max.y;
  return true;
}

//------------------------------------------------------------------------------
// Choose the channels that become the output components; see the class documentation.
bool SelectChannels(
  vtkOpenEXRHeader& header, const std::string& requestedLayer, vtkOpenEXRFailure& failure)
{
  std::vector<std::string> layers;
  for (const vtkOpenEXRChannel& channel : header.Channels)
  {
    if (std::find(layers.begin(), layers.end(), channel.Layer) == layers.end())
    {
      layers.push_back(channel.Layer);
    }
  }
  if (!requestedLayer.empty())
  {
    header.Layer = requestedLayer;
  }
  else if (std::find(layers.begin(), layers.end(), std::string()) != layers.end())
  {
    header.Layer.clear();
  }
  else
  {
    header.Layer = header.Channels.front().Layer;
  }
  if (std::find(layers.begin(), layers.end(), header.Layer) == layers.end())
  {
    return failure.Set(vtkErrorCode::UserError,
      "part has no layer '" + header.Layer + "'; its layers are " + JoinNames(layers));
  }

  auto find = [&header](const char* base)
  {
    for (size_t i = 0; i < header.Channels.size(); ++i)
    {
      if (header.Channels[i].Layer == header.Layer && header.Channels[i].Base == base)
      {
        return static_cast<int>(i);
      }
    }
    return -1;
  };
  const int r = find("R"), g = find("G"), b = find("B"), a = find("A");
  const int y = find("Y"), ry = find("RY"), by = find("BY");

  header.Decoded.clear();
  header.ComponentNames.clear();
  header.LuminanceChroma = false;
  if (y >= 0 && (ry >= 0 || by >= 0))
  {
    // Imf::RgbaInputFile performs the conversion (chroma reconstruction filter, YCA -> RGB
    // with the file's chromaticities); it reads the first part and expects 2x2 chroma.
    if (header.Part != 0)
    {
      return failure.Set(vtkErrorCode::FileFormatError,
        "luminance/chroma channels are supported only in the first part of a file");
    }
    for (int c : { y, a })
    {
      if (c >= 0 && (header.Channels[c].XSampling != 1 || header.Channels[c].YSampling != 1))
      {
        return failure.Set(vtkErrorCode::FileFormatError,
          "luminance/chroma channel '" + header.Channels[c].Name + "' is subsampled");
      }
    }
    for (int c : { ry, by })
    {
      if (c >= 0 && (header.Channels[c].XSampling != 2 || header.Channels[c].YSampling != 2))
      {
        return failure.Set(vtkErrorCode::FileFormatError,
          "chroma channel '" + header.Channels[c].Name + "' is not sampled 2x2");
      }
    }
    header.LuminanceChroma = true;
    for (int c : { y, ry, by, a })
    {
      if (c >= 0)
      {
        header.Decoded.push_back(c);
      }
    }
    header.ComponentNames = { "R", "G", "B" };
    if (a >= 0)
    {
      header.ComponentNames.emplace_back("A");
    }
    header.ScalarType = VTK_FLOAT;
    header.NumberOfComponents = static_cast<int>(header.ComponentNames.size());
    return true;
  }

  if (r >= 0 && g >= 0 && b >= 0)
  {
    header.Decoded = { r, g, b };
  }
  else if (y >= 0)
  {
    header.Decoded = { y };
  }
  if (!header.Decoded.empty())
  {
    if (a >= 0)
    {
      header.Decoded.push_back(a);
    }
  }
  else
  {
    // No recognised layout: the first channels of the layer, in file (name) order.
    for (size_t i = 0; i < header.Channels.size() && header.Decoded.size() < 4; ++i)
    {
      if (header.Channels[i].Layer == header.Layer)
      {
        header.Decoded.push_back(static_cast<int>(i));
      }
    }
  }

  bool allUnsigned = true;
  for (int c : header.Decoded)
  {
    const vtkOpenEXRChannel& channel = header.Channels[c];
    if (channel.XSampling != 1 || channel.YSampling != 1)
    {
      std::ostringstream message;
      message << "channel '" << channel.Name << "' is subsampled (" << channel.XSampling << "x"
              << channel.YSampling << "); only luminance/chroma data may be subsampled";
      return failure.Set(vtkErrorCode::FileFormatError, message.str());
    }
    allUnsigned = allUnsigned && channel.Type == EXR_PIXEL_UINT;
    header.ComponentNames.push_back(channel.Name);
  }
  header.ScalarType = allUnsigned ? VTK_UNSIGNED_INT : VTK_FLOAT;
  header.NumberOfComponents = static_cast<int>(header.Decoded.size());
  return true;
}

//------------------------------------------------------------------------------
// Read the part names and choose the part: the one named `partName` when that is given, else
// the one at `partIndex`.
bool ChoosePart(vtkOpenEXRCoreFile& file, int partIndex, const std::string& partName,
  vtkOpenEXRHeader& header, vtkOpenEXRFailure& failure)
{
  int count = 0;
  const exr_result_t result = exr_get_count(file.Context, &count);
  if (result != EXR_ERR_SUCCESS || count < 1)
  {
    return failure.Set(vtkErrorCode::FileFormatError, "the file has no parts");
  }
  header.PartNames.clear();
  for (int i = 0; i < count; ++i)
  {
    const char* name = nullptr;
    // Single-part files need not have a name; those report "".
    if (exr_get_name(file.Context, i, &name) != EXR_ERR_SUCCESS || !name)
    {
      name = "";
    }
    header.PartNames.emplace_back(name);
  }

  if (!partName.empty())
  {
    header.Part = -1;
    for (int i = 0; i < count && header.Part < 0; ++i)
    {
      if (header.PartNames[i] == partName)
      {
        header.Part = i;
      }
    }
    if (header.Part < 0)
    {
      return failure.Set(vtkErrorCode::UserError,
        "no part named '" + partName + "'; the parts are " + JoinNames(header.PartNames));
    }
  }
  else if (partIndex < 0 || partIndex >= count)
  {
    std::ostringstream message;
    message << "part index " << partIndex << " is out of range; the file has " << count
            << " part(s)";
    return failure.Set(vtkErrorCode::UserError, message.str());
  }
  else
  {
    header.Part = partIndex;
  }
  return true;
}

//------------------------------------------------------------------------------
// Read the part's channel list, each name split into its layer and base name at the last dot.
bool ReadChannels(
  vtkOpenEXRCoreFile& file, int part, vtkOpenEXRHeader& header, vtkOpenEXRFailure& failure)
{
  const exr_attr_chlist_t* channels = nullptr;
  const exr_result_t result = exr_get_channels(file.Context, part, &channels);
  if (result != EXR_ERR_SUCCESS || !channels || channels->num_channels < 1)
  {
    return failure.Set(vtkErrorCode::FileFormatError, "the part has no channels");
  }
  header.Channels.clear();
  for (int i = 0; i < channels->num_channels; ++i)
  {
    const exr_attr_chlist_entry_t& entry = channels->entries[i];
    vtkOpenEXRChannel channel;
    if (entry.name.str && entry.name.length > 0)
    {
      channel.Name.assign(entry.name.str, static_cast<size_t>(entry.name.length));
    }
    if (channel.Name.empty() || entry.pixel_type < EXR_PIXEL_UINT ||
      entry.pixel_type >= EXR_PIXEL_LAST_TYPE || entry.x_sampling < 1 || entry.y_sampling < 1)
    {
      return failure.Set(vtkErrorCode::FileFormatError, "invalid channel list");
    }
    const size_t dot = channel.Name.rfind('.');
    if (dot == std::string::npos)
    {
      channel.Base = channel.Name;
    }
    else
    {
      channel.Layer = channel.Name.substr(0, dot);
      channel.Base = channel.Name.substr(dot + 1);
    }
    channel.Type = entry.pixel_type;
    channel.XSampling = entry.x_sampling;
    channel.YSampling = entry.y_sampling;
    header.Channels.push_back(channel);
  }
  return true;
}

//------------------------------------------------------------------------------
// Refuse before allocating: width * height against the pixel limit, and the decoded output,
// width * height * components * 4 bytes, against the byte limit, with overflow checks.
bool CheckLimits(
  const vtkOpenEXRHeader& header, const vtkOpenEXRLimits& limits, vtkOpenEXRFailure& failure)
{
  vtkTypeUInt64 pixels = 0, bytes = 0;
  const vtkTypeUInt64 perPixel = 4u * static_cast<vtkTypeUInt64>(header.NumberOfComponents);
  const bool representable = CheckedMultiply(static_cast<vtkTypeUInt64>(header.Width),
                               static_cast<vtkTypeUInt64>(header.Height), pixels) &&
    CheckedMultiply(pixels, perPixel, bytes);
  if (!representable || pixels > limits.MaximumImagePixels)
  {
    std::ostringstream message;
    message << "image of " << header.Width << " x " << header.Height
            << " pixels exceeds MaximumImagePixels (" << limits.MaximumImagePixels
            << "); raise the limit to read it";
    return failure.Set(vtkErrorCode::FileFormatError, message.str());
  }
  if (bytes > limits.MaximumImageBytes)
  {
    std::ostringstream message;
    message << "image of " << header.Width << " x " << header.Height << " pixels x "
            << header.NumberOfComponents << " components (" << bytes
            << " bytes) exceeds MaximumImageBytes (" << limits.MaximumImageBytes
            << "); raise the limit to read it";
    return failure.Set(vtkErrorCode::FileFormatError, message.str());
  }
  // The decoder takes line strides as 32-bit integers.
  if (header.Width * header.NumberOfComponents * 4 > std::numeric_limits<int32_t>::max())
  {
    return failure.Set(vtkErrorCode::FileFormatError, "image rows are too wide to decode");
  }
  return true;
}

}

//------------------------------------------------------------------------------
bool vtkOpenEXRHeader::SameLayout(const vtkOpenEXRHeader& other) const
{
  return std::equal(this->DataWindow, this->DataWindow + 4, other.DataWindow) &&
    this->Part == other.Part && this->ScalarType == other.ScalarType &&
    this->NumberOfComponents == other.NumberOfComponents &&
    this->LuminanceChroma == other.LuminanceChroma && this->Compression == other.Compression;
}

//------------------------------------------------------------------------------
bool vtkOpenEXRReadHeader(vtkOpenEXRCoreFile& file, int partIndex, const std::string& partName,
  const std::string& layer, const vtkOpenEXRLimits& limits, vtkOpenEXRHeader& header,
  vtkOpenEXRFailure& failure)
{
  if (!ChoosePart(file, partIndex, partName, header, failure))
  {
    return false;
  }
  const int part = header.Part;

  exr_result_t result = exr_get_storage(file.Context, part, &header.Storage);
  if (result != EXR_ERR_SUCCESS)
  {
    return failure.Set(
      vtkErrorCode::FileFormatError, "cannot read the part type: " + file.Describe(result));
  }
  if (header.Storage != EXR_STORAGE_SCANLINE && header.Storage != EXR_STORAGE_TILED)
  {
    std::ostringstream message;
    message << "part " << part << " ('" << header.PartNames[part] << "') holds "
            << StorageName(header.Storage)
            << " data; deep images are not supported, only flat scanline and tiled parts";
    return failure.Set(vtkErrorCode::FileFormatError, message.str());
  }
  // An empty view list makes OpenEXR's luminance/chroma reader index its first view (a null
  // read in Imf::RgbaInputFile before 3.4.11, with no advisory; docs/openexr.md). No sound file
  // names no views, so it is refused for every part.
  const exr_attribute_t* views = nullptr;
  if (exr_get_attribute_by_name(file.Context, part, "multiView", &views) == EXR_ERR_SUCCESS &&
    views && views->type == EXR_ATTR_STRING_VECTOR &&
    (!views->stringvector || views->stringvector->n_strings < 1))
  {
    return failure.Set(vtkErrorCode::FileFormatError,
      "part " + std::to_string(part) + " has a multiView attribute that names no view");
  }
  if (!ReadWindow(file, part, true, header.DataWindow, failure) ||
    !ReadWindow(file, part, false, header.DisplayWindow, failure))
  {
    return false;
  }
  header.Width = static_cast<vtkTypeInt64>(header.DataWindow[1]) - header.DataWindow[0] + 1;
  header.Height = static_cast<vtkTypeInt64>(header.DataWindow[3]) - header.DataWindow[2] + 1;

  if (!ReadChannels(file, part, header, failure) || !SelectChannels(header, layer, failure))
  {
    return false;
  }

  result = exr_get_compression(file.Context, part, &header.Compression);
  if (result != EXR_ERR_SUCCESS || header.Compression < EXR_COMPRESSION_NONE ||
    header.Compression >= EXR_COMPRESSION_LAST_TYPE)
  {
    return failure.Set(vtkErrorCode::FileFormatError, "invalid compression");
  }
  return CheckLimits(header, limits, failure);
}

//------------------------------------------------------------------------------
vtkTypeUInt64 vtkOpenEXRMaximumExpansion(exr_compression_t compression)
{
  // A chunk whose compressed form would not be smaller is stored raw (packed == unpacked), so
  // these bounds apply only when a chunk is smaller than its decoded size. Each is the format's
  // own limit, with margin; docs/numerics.md lists the ratios measured on constant images.
  constexpr vtkTypeUInt64 deflate = 1032; // zlib's documented worst case: 1032:1
  switch (compression)
  {
    case EXR_COMPRESSION_NONE:
      return 1;
    case EXR_COMPRESSION_RLE:
      // A 2-byte run record repeats one byte at most 128 times.
      return 64;
    case EXR_COMPRESSION_ZIPS:
    case EXR_COMPRESSION_ZIP:
      return deflate;
    case EXR_COMPRESSION_PIZ:
      // Huffman codes of at least 1 bit, with run-length records of 8-bit counts: at most 255
      // 16-bit values per 9 bits (453:1).
      return 1024;
    case EXR_COMPRESSION_PXR24:
      // Deflate over 24-bit floats: 4/3 of deflate's bound.
      return deflate * 4 / 3 + 1;
    case EXR_COMPRESSION_B44:
    case EXR_COMPRESSION_B44A:
      // A 4x4 block of half values (32 bytes) in 14 bytes, or 3 when flat (B44A); other
      // channel types are stored raw.
      return 11;
    case EXR_COMPRESSION_DWAA:
    case EXR_COMPRESSION_DWAB:
      // Run-length coding (64:1) followed by deflate (1032:1) for RLE channels; DCT blocks of
      // 64 values reduce to 2 DC and 2 AC bytes before deflate, which is the same bound.
      return 2 * 64 * deflate;
    default:
      return 0;
  }
}

//------------------------------------------------------------------------------
bool vtkOpenEXRReadChunkTable(vtkOpenEXRCoreFile& file, const vtkOpenEXRHeader& header,
  const vtkOpenEXRLimits& limits, std::vector<vtkOpenEXRChunk>& chunks, vtkOpenEXRFailure& failure)
{
  chunks.clear();
  const int part = header.Part;
  const vtkTypeInt64 x0 = header.DataWindow[0], y0 = header.DataWindow[2];
  const vtkTypeInt64 x1 = header.DataWindow[1], y1 = header.DataWindow[3];

  // The decoder allocates one decompressed chunk holding every channel of the part, selected
  // or not, so it needs its own bound.
  uint64_t chunkBytes = 0;
  exr_result_t result = exr_get_chunk_unpacked_size(file.Context, part, &chunkBytes);
  if (result != EXR_ERR_SUCCESS || chunkBytes > limits.MaximumImageBytes)
  {
    std::ostringstream message;
    message << "a decompressed chunk of " << chunkBytes
            << " bytes exceeds MaximumImageBytes or is invalid";
    return failure.Set(vtkErrorCode::FileFormatError, message.str());
  }

  // Each chunk needs at least an 8-byte offset-table entry and a chunk header in the file, so
  // a plausible chunk count is bounded by the file size; this stops a tiny file that claims
  // millions of chunks before we iterate over them.
  int32_t chunkCount = 0;
  result = exr_get_chunk_count(file.Context, part, &chunkCount);
  if (result != EXR_ERR_SUCCESS)
  {
    return failure.Set(
      vtkErrorCode::FileFormatError, "cannot read the chunk count: " + file.Describe(result));
  }
  if (chunkCount < 1 || chunkCount > file.FileSize / 16)
  {
    std::ostringstream message;
    message << "the part has " << chunkCount << " pixel data chunks, which a file of "
            << file.FileSize << " bytes cannot hold";
    return failure.Set(vtkErrorCode::FileFormatError, message.str());
  }

  vtkTypeInt64 stepX = header.Width, stepY = 1;
  if (header.Storage == EXR_STORAGE_SCANLINE)
  {
    int32_t lines = 0;
    result = exr_get_scanlines_per_chunk(file.Context, part, &lines);
    if (result != EXR_ERR_SUCCESS || lines < 1)
    {
      return failure.Set(vtkErrorCode::FileFormatError,
        "cannot read the scanlines per chunk: " + file.Describe(result));
    }
    stepY = lines;
  }
  else
  {
    uint32_t tileX = 0, tileY = 0;
    exr_tile_level_mode_t levels;
    exr_tile_round_mode_t rounding;
    result = exr_get_tile_descriptor(file.Context, part, &tileX, &tileY, &levels, &rounding);
    if (result != EXR_ERR_SUCCESS || tileX < 1 || tileY < 1)
    {
      return failure.Set(vtkErrorCode::FileFormatError,
        "cannot read the tile description: " + file.Describe(result));
    }
    stepX = tileX;
    stepY = tileY;
  }

  const vtkTypeInt64 countX = (header.Width + stepX - 1) / stepX;
  const vtkTypeInt64 countY = (header.Height + stepY - 1) / stepY;
  // Level 0 is part of the chunk table, so this also bounds the loop below by the file size.
  if (countX * countY > chunkCount)
  {
    return failure.Set(
      vtkErrorCode::FileFormatError, "the chunk count does not cover the data window");
  }
  // OpenEXR 3.1's PIZ decoders (the core's and the C++ library's) index a chunk's wavelet
  // buffers with 32-bit products that overflow from 2^30 samples of a channel in one chunk
  // (CVE-2026-34588, fixed in 3.2.7). The default pixel limit keeps chunks far below that; a
  // raised one must not let them reach it. 2^29 leaves a factor 2 of margin.
  if (header.Compression == EXR_COMPRESSION_PIZ &&
    std::min<vtkTypeInt64>(stepX, x1 - x0 + 1) * std::min<vtkTypeInt64>(stepY, y1 - y0 + 1) >=
      (vtkTypeInt64(1) << 29))
  {
    return failure.Set(vtkErrorCode::FileFormatError,
      "its PIZ chunks hold 2^29 or more pixels, which overflow OpenEXR 3.1's PIZ decoder "
      "(CVE-2026-34588)");
  }
  const vtkTypeUInt64 expansion = vtkOpenEXRMaximumExpansion(header.Compression);
  const auto fileSize = static_cast<uint64_t>(file.FileSize);
  chunks.reserve(static_cast<size_t>(countX * countY));
  for (vtkTypeInt64 j = 0; j < countY; ++j)
  {
    for (vtkTypeInt64 i = 0; i < countX; ++i)
    {
      vtkOpenEXRChunk chunk;
      exr_chunk_info_t& info = chunk.Info;
      result = header.Storage == EXR_STORAGE_SCANLINE
        ? exr_read_scanline_chunk_info(file.Context, part, static_cast<int>(y0 + j * stepY), &info)
        : exr_read_tile_chunk_info(
            file.Context, part, static_cast<int>(i), static_cast<int>(j), 0, 0, &info);
      if (result != EXR_ERR_SUCCESS)
      {
        const unsigned long code = result == EXR_ERR_READ_IO ? vtkErrorCode::PrematureEndOfFileError
                                                             : vtkErrorCode::FileFormatError;
        return failure.Set(code, "invalid pixel data chunk: " + file.Describe(result));
      }
      const vtkTypeInt64 startX = x0 + i * stepX, startY = y0 + j * stepY;
      const vtkTypeInt64 width = std::min(stepX, x1 - startX + 1);
      const vtkTypeInt64 height = std::min(stepY, y1 - startY + 1);
      // The library reports scanline chunks by pixel position and tiles by tile index.
      const bool placed = header.Storage == EXR_STORAGE_SCANLINE
        ? (info.start_x == startX && info.start_y == startY)
        : (info.start_x == i && info.start_y == j && info.level_x == 0 && info.level_y == 0);
      if (!placed || info.width != width || info.height != height || info.packed_size > fileSize ||
        info.data_offset > fileSize - info.packed_size)
      {
        return failure.Set(vtkErrorCode::FileFormatError,
          "a pixel data chunk does not match the data window or lies outside the file");
      }
      // The decoded size comes from the header; the compressed bytes must be able to hold it.
      // Without this, a file of a few hundred bytes whose header claims gigabytes would have
      // them allocated (and, for uncompressed chunks, "decoded") before anything failed.
      if (info.unpacked_size > info.packed_size &&
        info.unpacked_size / expansion + (info.unpacked_size % expansion != 0) > info.packed_size)
      {
        std::ostringstream message;
        message << "a pixel data chunk of " << info.packed_size
                << " compressed bytes cannot hold the " << info.unpacked_size
                << " bytes its header claims (chunk " << (j * countX + i) << " of "
                << countX * countY << ")";
        return failure.Set(vtkErrorCode::FileFormatError, message.str());
      }
      chunk.StartX = static_cast<int32_t>(startX);
      chunk.StartY = static_cast<int32_t>(startY);
      chunks.push_back(chunk);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
std::string vtkOpenEXRChunk::Describe() const
{
  static const char* const codecs[] = { "uncompressed", "RLE", "ZIPS", "ZIP", "PIZ", "PXR24", "B44",
    "B44A", "DWAA", "DWAB" };
  const char* codec = this->Info.compression < sizeof(codecs) / sizeof(codecs[0])
    ? codecs[this->Info.compression]
    : "unknown";
  std::ostringstream text;
  text << "the " << codec << " chunk of pixels (" << this->StartX << ", " << this->StartY
       << ") to (" << this->StartX + this->Info.width - 1 << ", "
       << this->StartY + this->Info.height - 1 << "), " << this->Info.packed_size << " bytes for "
       << this->Info.unpacked_size;
  return text.str();
}

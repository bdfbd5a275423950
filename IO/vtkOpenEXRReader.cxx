#include "vtkOpenEXRReader.h"

#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkUnsignedIntArray.h"

#include <ImfRgba.h>
#include <ImfRgbaFile.h>
#include <openexr.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

vtkStandardNewMacro(vtkOpenEXRReader);

namespace
{
//------------------------------------------------------------------------------
// A failure: the message for vtkErrorMacro and the vtkErrorCode for the caller.
struct vtkOpenEXRFailure
{
  unsigned long Code = vtkErrorCode::NoError;
  std::string Message;

  bool Set(unsigned long code, const std::string& message)
  {
    this->Code = code;
    // Library messages quote names from the damaged header verbatim; keep control bytes and
    // binary junk out of the log, and keep the message short.
    this->Message.clear();
    for (const char c : message.substr(0, 400))
    {
      const auto u = static_cast<unsigned char>(c);
      this->Message += (u >= 0x20 && u < 0x7f) ? c : '?';
    }
    return false;
  }
};

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
// What the header says about the selected part, and how it maps to the output.
struct vtkOpenEXRHeader
{
  std::vector<std::string> PartNames;
  int Part = -1;
  exr_storage_t Storage = EXR_STORAGE_SCANLINE;
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
  int ScalarType = VTK_FLOAT;
  int NumberOfComponents = 0;

  bool SameLayout(const vtkOpenEXRHeader& other) const
  {
    for (int i = 0; i < 4; ++i)
    {
      if (this->DataWindow[i] != other.DataWindow[i])
      {
        return false;
      }
    }
    return this->Part == other.Part && this->ScalarType == other.ScalarType &&
      this->NumberOfComponents == other.NumberOfComponents &&
      this->LuminanceChroma == other.LuminanceChroma;
  }
};

//------------------------------------------------------------------------------
// An OpenEXR core-library read context on a file we open ourselves. Owning the stream lets
// the error callback reach this object through the context's user data, and lets the reads
// refuse anything past the end of the file.
class vtkOpenEXRCoreFile
{
public:
  vtkOpenEXRCoreFile() = default;
  ~vtkOpenEXRCoreFile() { this->Close(); }
  vtkOpenEXRCoreFile(const vtkOpenEXRCoreFile&) = delete;
  vtkOpenEXRCoreFile& operator=(const vtkOpenEXRCoreFile&) = delete;

  bool Open(const std::string& fileName, vtkOpenEXRFailure& failure);

  void Close()
  {
    if (this->Context)
    {
      exr_finish(&this->Context);
      this->Context = nullptr;
    }
  }

  // The library's own message for the last failure when it gave one, else the generic text.
  std::string Describe(exr_result_t result)
  {
    std::string message = this->LastMessage.empty()
      ? std::string(exr_get_default_error_message(result))
      : this->LastMessage;
    this->LastMessage.clear();
    return message;
  }

  exr_context_t Context = nullptr;
  vtkTypeInt64 FileSize = 0;

private:
  static int64_t Read(exr_const_context_t, void* userData, void* buffer, uint64_t size,
    uint64_t offset, exr_stream_error_func_ptr_t);
  static int64_t QuerySize(exr_const_context_t, void* userData);
  static void Error(exr_const_context_t context, exr_result_t, const char* message);

  std::ifstream Stream;
  std::string LastMessage;
};

//------------------------------------------------------------------------------
int64_t vtkOpenEXRCoreFile::Read(exr_const_context_t, void* userData, void* buffer, uint64_t size,
  uint64_t offset, exr_stream_error_func_ptr_t)
{
  auto* self = static_cast<vtkOpenEXRCoreFile*>(userData);
  const auto fileSize = static_cast<uint64_t>(self->FileSize);
  if (offset >= fileSize)
  {
    return 0;
  }
  // A short read tells the library that the file ended early.
  const uint64_t count = std::min(size, fileSize - offset);
  self->Stream.clear();
  self->Stream.seekg(static_cast<std::streamoff>(offset), std::ios::beg);
  if (!self->Stream)
  {
    return -1;
  }
  self->Stream.read(static_cast<char*>(buffer), static_cast<std::streamsize>(count));
  return static_cast<int64_t>(self->Stream.gcount());
}

//------------------------------------------------------------------------------
int64_t vtkOpenEXRCoreFile::QuerySize(exr_const_context_t, void* userData)
{
  return static_cast<vtkOpenEXRCoreFile*>(userData)->FileSize;
}

//------------------------------------------------------------------------------
void vtkOpenEXRCoreFile::Error(exr_const_context_t context, exr_result_t, const char* message)
{
  // The library reports details here and returns only a code; keep the text for our error.
  void* userData = nullptr;
  if (exr_get_user_data(context, &userData) == EXR_ERR_SUCCESS && userData && message)
  {
    static_cast<vtkOpenEXRCoreFile*>(userData)->LastMessage = message;
  }
}

//------------------------------------------------------------------------------
bool vtkOpenEXRCoreFile::Open(const std::string& fileName, vtkOpenEXRFailure& failure)
{
  this->Close();
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path path(fileName);
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status))
  {
    return failure.Set(vtkErrorCode::FileNotFoundError, "file does not exist");
  }
  if (fs::is_directory(status))
  {
    return failure.Set(vtkErrorCode::CannotOpenFileError, "is a directory, not a file");
  }
  // Devices and pipes have no size and may block forever; only plain files are read.
  if (!fs::is_regular_file(status))
  {
    return failure.Set(vtkErrorCode::CannotOpenFileError, "is not a regular file");
  }
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec || size > static_cast<std::uintmax_t>(std::numeric_limits<int64_t>::max()))
  {
    return failure.Set(vtkErrorCode::CannotOpenFileError, "cannot determine the file size");
  }
  if (size == 0)
  {
    return failure.Set(vtkErrorCode::PrematureEndOfFileError, "file is empty");
  }
  this->FileSize = static_cast<vtkTypeInt64>(size);
  this->Stream.close();
  this->Stream.clear();
  this->Stream.open(path, std::ios::in | std::ios::binary);
  if (!this->Stream)
  {
    return failure.Set(vtkErrorCode::CannotOpenFileError, "cannot open the file for reading");
  }

  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = &vtkOpenEXRCoreFile::Error;
  init.user_data = this;
  init.read_fn = &vtkOpenEXRCoreFile::Read;
  init.size_fn = &vtkOpenEXRCoreFile::QuerySize;
  // Strict mode refuses the damage that the C++ library would paper over, such as a missing
  // required attribute or a chunkCount that contradicts the data window.
  init.flags = EXR_CONTEXT_FLAG_STRICT_HEADER;
  this->LastMessage.clear();
  const exr_result_t result = exr_start_read(&this->Context, fileName.c_str(), &init);
  if (result != EXR_ERR_SUCCESS)
  {
    // exr_start_read releases the context itself when it fails.
    this->Context = nullptr;
    const unsigned long code = result == EXR_ERR_READ_IO ? vtkErrorCode::PrematureEndOfFileError
                                                         : vtkErrorCode::FileFormatError;
    return failure.Set(code, "not a valid OpenEXR file: " + this->Describe(result));
  }
  return true;
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
// Parse and validate everything the reader needs from the header of the selected part.
bool ReadHeader(vtkOpenEXRCoreFile& file, int partIndex, const std::string& partName,
  const std::string& layer, vtkTypeUInt64 maximumBytes, vtkOpenEXRHeader& header,
  vtkOpenEXRFailure& failure)
{
  int count = 0;
  exr_result_t result = exr_get_count(file.Context, &count);
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
  const int part = header.Part;

  result = exr_get_storage(file.Context, part, &header.Storage);
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
  if (!ReadWindow(file, part, true, header.DataWindow, failure) ||
    !ReadWindow(file, part, false, header.DisplayWindow, failure))
  {
    return false;
  }
  header.Width = static_cast<vtkTypeInt64>(header.DataWindow[1]) - header.DataWindow[0] + 1;
  header.Height = static_cast<vtkTypeInt64>(header.DataWindow[3]) - header.DataWindow[2] + 1;

  const exr_attr_chlist_t* channels = nullptr;
  result = exr_get_channels(file.Context, part, &channels);
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

  if (!SelectChannels(header, layer, failure))
  {
    return false;
  }

  // Refuse before allocating: width * height * (components * 4 [+ 8 for the half RGBA
  // buffer of the luminance/chroma conversion]) with overflow checks.
  vtkTypeUInt64 pixels = 0, bytes = 0;
  const vtkTypeUInt64 perPixel =
    4u * static_cast<vtkTypeUInt64>(header.NumberOfComponents) + (header.LuminanceChroma ? 8 : 0);
  if (!CheckedMultiply(static_cast<vtkTypeUInt64>(header.Width),
        static_cast<vtkTypeUInt64>(header.Height), pixels) ||
    !CheckedMultiply(pixels, perPixel, bytes) || bytes > maximumBytes)
  {
    std::ostringstream message;
    message << "image of " << header.Width << " x " << header.Height << " pixels x "
            << header.NumberOfComponents << " components exceeds MaximumImageBytes ("
            << maximumBytes << ")";
    return failure.Set(vtkErrorCode::FileFormatError, message.str());
  }
  // The decoder takes line strides as 32-bit integers.
  if (header.Width * header.NumberOfComponents * 4 > std::numeric_limits<int32_t>::max())
  {
    return failure.Set(vtkErrorCode::FileFormatError, "image rows are too wide to decode");
  }
  return true;
}

//------------------------------------------------------------------------------
// Visit every chunk of level 0 of the selected part in order, after checking that it is where
// the data window says it must be, so that decoding can never write outside the image. The
// visitor gets the chunk and the pixel coordinates of its first pixel.
template <typename Visitor>
bool ForEachChunk(vtkOpenEXRCoreFile& file, const vtkOpenEXRHeader& header,
  vtkOpenEXRFailure& failure, Visitor&& visit)
{
  const int part = header.Part;
  const vtkTypeInt64 x0 = header.DataWindow[0], y0 = header.DataWindow[2];
  const vtkTypeInt64 x1 = header.DataWindow[1], y1 = header.DataWindow[3];

  // Each chunk needs at least an 8-byte offset-table entry and a chunk header in the file, so
  // a plausible chunk count is bounded by the file size; this stops a tiny file that claims
  // millions of chunks before we iterate over them.
  int32_t chunkCount = 0;
  exr_result_t result = exr_get_chunk_count(file.Context, part, &chunkCount);
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
  for (vtkTypeInt64 j = 0; j < countY; ++j)
  {
    for (vtkTypeInt64 i = 0; i < countX; ++i)
    {
      exr_chunk_info_t chunk;
      result = header.Storage == EXR_STORAGE_SCANLINE
        ? exr_read_scanline_chunk_info(file.Context, part, static_cast<int>(y0 + j * stepY), &chunk)
        : exr_read_tile_chunk_info(
            file.Context, part, static_cast<int>(i), static_cast<int>(j), 0, 0, &chunk);
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
        ? (chunk.start_x == startX && chunk.start_y == startY)
        : (chunk.start_x == i && chunk.start_y == j && chunk.level_x == 0 && chunk.level_y == 0);
      const auto fileSize = static_cast<uint64_t>(file.FileSize);
      if (!placed || chunk.width != width || chunk.height != height ||
        chunk.packed_size > fileSize || chunk.data_offset > fileSize - chunk.packed_size)
      {
        return failure.Set(vtkErrorCode::FileFormatError,
          "a pixel data chunk does not match the data window or lies outside the file");
      }
      const double fraction = static_cast<double>(j * countX + i + 1) / (countX * countY);
      if (!visit(chunk, static_cast<int32_t>(startX), static_cast<int32_t>(startY), fraction))
      {
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// Frees the decoder's buffers however a chunk loop ends.
struct vtkOpenEXRDecoder
{
  exr_const_context_t Context;
  exr_decode_pipeline_t Pipeline{}; // zeroed, as EXR_DECODE_PIPELINE_INITIALIZER
  bool Initialized = false;

  explicit vtkOpenEXRDecoder(exr_const_context_t context)
    : Context(context)
  {
  }
  ~vtkOpenEXRDecoder()
  {
    if (this->Initialized)
    {
      exr_decoding_destroy(this->Context, &this->Pipeline);
    }
  }
  vtkOpenEXRDecoder(const vtkOpenEXRDecoder&) = delete;
  vtkOpenEXRDecoder& operator=(const vtkOpenEXRDecoder&) = delete;

  exr_result_t Start(int part, const exr_chunk_info_t& chunk)
  {
    if (this->Initialized)
    {
      return exr_decoding_update(this->Context, part, &chunk, &this->Pipeline);
    }
    const exr_result_t result =
      exr_decoding_initialize(this->Context, part, &chunk, &this->Pipeline);
    // A failed initialize may still have allocated; destroy is safe on a zeroed pipeline.
    this->Initialized = true;
    return result;
  }
};

//------------------------------------------------------------------------------
// Check the whole chunk table of the selected part, and the largest decompressed chunk, before
// any pixel memory is allocated: a header that promises a large image backed by a missing or
// broken table then costs nothing.
bool ValidateChunks(vtkOpenEXRCoreFile& file, const vtkOpenEXRHeader& header,
  vtkTypeUInt64 maximumBytes, vtkOpenEXRFailure& failure)
{
  // The decoder allocates one decompressed chunk holding every channel of the part, selected
  // or not, so it needs its own bound.
  uint64_t chunkBytes = 0;
  const exr_result_t result = exr_get_chunk_unpacked_size(file.Context, header.Part, &chunkBytes);
  if (result != EXR_ERR_SUCCESS || chunkBytes > maximumBytes)
  {
    std::ostringstream message;
    message << "a decompressed chunk of " << chunkBytes
            << " bytes exceeds MaximumImageBytes or is invalid";
    return failure.Set(vtkErrorCode::FileFormatError, message.str());
  }
  return ForEachChunk(
    file, header, failure, [](const exr_chunk_info_t&, int32_t, int32_t, double) { return true; });
}

//------------------------------------------------------------------------------
// Little-endian loads (the EXR byte order) that work on any host and any alignment.
inline uint32_t LoadLE32(const uint8_t* p)
{
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) |
    (static_cast<uint32_t>(p[2]) << 16) | (static_cast<uint32_t>(p[3]) << 24);
}

inline uint16_t LoadLE16(const uint8_t* p)
{
  return static_cast<uint16_t>(p[0] | (p[1] << 8));
}

//------------------------------------------------------------------------------
// Exact half -> float widening on the bit level. Every half, NaN payloads (signalling ones
// included) and subnormals too, maps to the float of identical value: the mantissa is shifted
// into place and the exponent rebiased, so nothing is quieted or rounded.
inline float HalfBitsToFloat(uint16_t half)
{
  const uint32_t sign = static_cast<uint32_t>(half & 0x8000u) << 16;
  uint32_t exponent = (half >> 10) & 0x1fu;
  uint32_t mantissa = half & 0x3ffu;
  uint32_t bits;
  if (exponent == 0x1fu)
  {
    bits = sign | 0x7f800000u | (mantissa << 13);
  }
  else if (exponent != 0)
  {
    bits = sign | ((exponent + 112u) << 23) | (mantissa << 13);
  }
  else if (mantissa == 0)
  {
    bits = sign;
  }
  else
  {
    // Subnormal half: normalise; every such value is a normal float.
    exponent = 113u;
    while ((mantissa & 0x400u) == 0)
    {
      mantissa <<= 1;
      --exponent;
    }
    bits = sign | (exponent << 23) | ((mantissa & 0x3ffu) << 13);
  }
  float value;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

//------------------------------------------------------------------------------
// Decode every chunk of the selected part with the core library. The library only reads and
// decompresses; the unpacking into the interleaved output is ours: the core library's fast
// interleaving paths of this release assume the output components are in file (alphabetical)
// order, which R, G, B, A is not. With `output` null, chunks are only decompressed and their
// layout checked, which validates luminance/chroma files before the C++ library sees them.
bool DecodeCore(vtkOpenEXRCoreFile& file, const vtkOpenEXRHeader& header, void* output,
  bool unsignedOutput, vtkAlgorithm* progress, vtkOpenEXRFailure& failure)
{
  vtkOpenEXRDecoder decoder(file.Context);
  const size_t components = static_cast<size_t>(header.NumberOfComponents);
  const size_t width = static_cast<size_t>(header.Width);
  std::vector<int> componentOf;

  return ForEachChunk(file, header, failure,
    [&](const exr_chunk_info_t& chunk, int32_t startX, int32_t startY, double fraction)
    {
      auto corrupt = [&](exr_result_t result)
      {
        return failure.Set(vtkErrorCode::FileFormatError,
          "cannot decode a pixel data chunk: " + file.Describe(result));
      };
      exr_result_t result = decoder.Start(header.Part, chunk);
      exr_decode_pipeline_t& pipeline = decoder.Pipeline;
      if (result == EXR_ERR_SUCCESS)
      {
        // With no destination pointers this picks only the read and decompress steps.
        for (int16_t c = 0; c < pipeline.channel_count; ++c)
        {
          pipeline.channels[c].decode_to_ptr = nullptr;
        }
        result = exr_decoding_choose_default_routines(file.Context, header.Part, &pipeline);
      }
      if (result == EXR_ERR_SUCCESS)
      {
        pipeline.unpack_and_convert_fn = nullptr;
        result = exr_decoding_run(file.Context, header.Part, &pipeline);
      }
      if (result != EXR_ERR_SUCCESS)
      {
        return corrupt(result);
      }

      // The decompressed chunk holds, line by line, each channel that has samples on that line
      // (y divisible by its y sampling), in channel-list order. Check that the layout the
      // library describes accounts for exactly the bytes it produced before walking it.
      componentOf.assign(static_cast<size_t>(pipeline.channel_count), -1);
      uint64_t expectedBytes = 0;
      for (int16_t c = 0; c < pipeline.channel_count; ++c)
      {
        const exr_coding_channel_info_t& channel = pipeline.channels[c];
        if (channel.y_samples < 1)
        {
          return failure.Set(vtkErrorCode::FileFormatError, "invalid channel sampling");
        }
        int32_t lines = 0;
        for (int32_t line = 0; line < chunk.height; ++line)
        {
          lines += (startY + line) % channel.y_samples == 0 ? 1 : 0;
        }
        if (channel.width < 0 || channel.height != lines || channel.x_samples < 1 ||
          (channel.bytes_per_element != 2 && channel.bytes_per_element != 4) ||
          (channel.x_samples == 1 && channel.width != chunk.width))
        {
          return failure.Set(
            vtkErrorCode::FileFormatError, "a pixel data chunk does not match the channel layout");
        }
        expectedBytes += static_cast<uint64_t>(channel.width) * static_cast<uint64_t>(lines) *
          static_cast<uint64_t>(channel.bytes_per_element);
        for (size_t k = 0; k < header.Decoded.size(); ++k)
        {
          if (header.Channels[header.Decoded[k]].Name == channel.channel_name)
          {
            componentOf[c] = static_cast<int>(k);
          }
        }
      }
      if (expectedBytes != chunk.unpacked_size || (expectedBytes > 0 && !pipeline.unpacked_buffer))
      {
        return failure.Set(
          vtkErrorCode::FileFormatError, "a pixel data chunk does not match the channel layout");
      }

      if (output)
      {
        const uint8_t* in = static_cast<const uint8_t*>(pipeline.unpacked_buffer);
        for (int32_t line = 0; line < chunk.height; ++line)
        {
          const int32_t y = startY + line;
          const size_t row = static_cast<size_t>(y - header.DataWindow[2]);
          const size_t column = static_cast<size_t>(startX - header.DataWindow[0]);
          for (int16_t c = 0; c < pipeline.channel_count; ++c)
          {
            const exr_coding_channel_info_t& channel = pipeline.channels[c];
            if (y % channel.y_samples != 0)
            {
              continue;
            }
            const size_t count = static_cast<size_t>(channel.width);
            const int bytes = channel.bytes_per_element;
            if (componentOf[c] >= 0)
            {
              // Selected channels are full resolution (SelectChannels), so count == chunk width.
              const size_t first =
                (row * width + column) * components + static_cast<size_t>(componentOf[c]);
              if (unsignedOutput)
              {
                uint32_t* out = static_cast<uint32_t*>(output) + first;
                for (size_t x = 0; x < count; ++x, out += components)
                {
                  *out = LoadLE32(in + x * 4);
                }
              }
              else
              {
                float* out = static_cast<float*>(output) + first;
                for (size_t x = 0; x < count; ++x, out += components)
                {
                  const uint8_t* value = in + x * static_cast<size_t>(bytes);
                  if (channel.data_type == EXR_PIXEL_HALF)
                  {
                    *out = HalfBitsToFloat(LoadLE16(value));
                  }
                  else if (channel.data_type == EXR_PIXEL_FLOAT)
                  {
                    const uint32_t bits = LoadLE32(value);
                    std::memcpy(out, &bits, sizeof(bits));
                  }
                  else
                  {
                    // UINT among float channels: the nearest float (exact below 2^24).
                    *out = static_cast<float>(LoadLE32(value));
                  }
                }
              }
            }
            in += count * static_cast<size_t>(bytes);
          }
        }
      }
      progress->UpdateProgress(fraction * (output ? 1.0 : 0.5));
      return !progress->GetAbortExecute() ||
        failure.Set(vtkErrorCode::UnknownError, "reading was aborted");
    });
}

//------------------------------------------------------------------------------
// Luminance/chroma: Imf::RgbaInputFile reconstructs the subsampled chroma and converts to RGB.
// It runs only on files whose header and chunks the core library has already validated.
bool ConvertLuminanceChroma(const std::string& fileName, const vtkOpenEXRHeader& header,
  float* output, vtkOpenEXRFailure& failure)
{
  try
  {
    Imf::RgbaInputFile input(fileName.c_str(), header.Layer);
    const Imath::Box2i window = input.dataWindow();
    if (window.min.x != header.DataWindow[0] || window.max.x != header.DataWindow[1] ||
      window.min.y != header.DataWindow[2] || window.max.y != header.DataWindow[3])
    {
      return failure.Set(vtkErrorCode::FileFormatError, "inconsistent data window");
    }
    const size_t width = static_cast<size_t>(header.Width);
    const size_t count = width * static_cast<size_t>(header.Height);
    std::vector<Imf::Rgba> pixels(count);
    // The frame buffer is addressed by absolute pixel coordinates; compute its origin with
    // integer arithmetic because the pointer itself lies outside the vector.
    const vtkTypeInt64 origin =
      static_cast<vtkTypeInt64>(header.DataWindow[2]) * header.Width + header.DataWindow[0];
    const uintptr_t base = reinterpret_cast<uintptr_t>(pixels.data()) -
      static_cast<uintptr_t>(origin) * sizeof(Imf::Rgba);
    input.setFrameBuffer(reinterpret_cast<Imf::Rgba*>(base), 1, width);
    input.readPixels(header.DataWindow[2], header.DataWindow[3]);

    const int components = header.NumberOfComponents;
    for (size_t p = 0; p < count; ++p)
    {
      float* out = output + p * static_cast<size_t>(components);
      out[0] = pixels[p].r;
      out[1] = pixels[p].g;
      out[2] = pixels[p].b;
      if (components == 4)
      {
        out[3] = pixels[p].a;
      }
    }
    return true;
  }
  catch (const std::bad_alloc&)
  {
    return failure.Set(vtkErrorCode::UnknownError, "out of memory");
  }
  catch (const std::exception& e)
  {
    return failure.Set(vtkErrorCode::FileFormatError, e.what());
  }
  catch (...)
  {
    return failure.Set(vtkErrorCode::UnknownError, "unknown exception from OpenEXR");
  }
}
}

//------------------------------------------------------------------------------
class vtkOpenEXRReader::vtkInternals
{
public:
  vtkOpenEXRHeader Header;
  bool HeaderValid = false;
  vtkNew<vtkStringArray> ChannelNames;
  vtkNew<vtkStringArray> ComponentNames;
};

//------------------------------------------------------------------------------
vtkOpenEXRReader::vtkOpenEXRReader()
  : FileName(nullptr)
  , PartIndex(0)
  , PartName(nullptr)
  , Layer(nullptr)
  , MaximumImageBytes(vtkTypeUInt64(4) << 30)
  , SelectedPartIndex(-1)
  , DataWindow{ 0, -1, 0, -1 }
  , DisplayWindow{ 0, -1, 0, -1 }
  , Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkOpenEXRReader::~vtkOpenEXRReader()
{
  this->SetFileName(nullptr);
  this->SetPartName(nullptr);
  this->SetLayer(nullptr);
}

//------------------------------------------------------------------------------
int vtkOpenEXRReader::CanReadFile(const char* fname)
{
  if (!fname)
  {
    return 0;
  }
  vtkOpenEXRCoreFile file;
  vtkOpenEXRFailure failure;
  return file.Open(fname, failure) ? 3 : 0;
}

//------------------------------------------------------------------------------
int vtkOpenEXRReader::GetNumberOfParts()
{
  return static_cast<int>(this->Internals->Header.PartNames.size());
}

//------------------------------------------------------------------------------
const char* vtkOpenEXRReader::GetPartName(int index)
{
  const std::vector<std::string>& names = this->Internals->Header.PartNames;
  return index >= 0 && index < static_cast<int>(names.size()) ? names[index].c_str() : nullptr;
}

//------------------------------------------------------------------------------
vtkStringArray* vtkOpenEXRReader::GetChannelNames()
{
  return this->Internals->ChannelNames;
}

//------------------------------------------------------------------------------
vtkStringArray* vtkOpenEXRReader::GetComponentNames()
{
  return this->Internals->ComponentNames;
}

//------------------------------------------------------------------------------
int vtkOpenEXRReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  this->SetErrorCode(vtkErrorCode::NoError);
  vtkInternals& internals = *this->Internals;
  internals.HeaderValid = false;
  internals.Header = vtkOpenEXRHeader();
  internals.ChannelNames->Initialize();
  internals.ComponentNames->Initialize();
  this->SelectedPartIndex = -1;
  for (int i = 0; i < 4; ++i)
  {
    this->DataWindow[i] = this->DisplayWindow[i] = (i % 2 == 0) ? 0 : -1;
  }

  // An empty whole extent makes downstream filters see "no data" rather than a stale image.
  static const int emptyExtent[6] = { 0, -1, 0, -1, 0, -1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), emptyExtent, 6);
  if (vtkImageData* output = vtkImageData::SafeDownCast(outInfo->Get(vtkDataObject::DATA_OBJECT())))
  {
    output->Initialize();
  }

  vtkOpenEXRFailure failure;
  vtkOpenEXRCoreFile file;
  if (!this->FileName || !*this->FileName)
  {
    failure.Set(vtkErrorCode::NoFileNameError, "no file name was set");
  }
  else if (file.Open(this->FileName, failure))
  {
    ReadHeader(file, this->PartIndex, this->PartName ? this->PartName : "",
      this->Layer ? this->Layer : "", this->MaximumImageBytes, internals.Header, failure);
  }
  const vtkOpenEXRHeader& header = internals.Header;
  // Whatever was learnt before a failure (the part list, say) stays available to the caller.
  for (const vtkOpenEXRChannel& channel : header.Channels)
  {
    internals.ChannelNames->InsertNextValue(channel.Name);
  }
  if (failure.Code != vtkErrorCode::NoError)
  {
    this->SetErrorCode(failure.Code);
    vtkErrorMacro("Cannot read OpenEXR file '" << (this->FileName ? this->FileName : "")
                                               << "': " << failure.Message);
    return 1;
  }

  for (const std::string& name : header.ComponentNames)
  {
    internals.ComponentNames->InsertNextValue(name);
  }
  this->SelectedPartIndex = header.Part;
  for (int i = 0; i < 4; ++i)
  {
    this->DataWindow[i] = header.DataWindow[i];
    this->DisplayWindow[i] = header.DisplayWindow[i];
  }
  const int extent[6] = { header.DataWindow[0], header.DataWindow[1], header.DataWindow[2],
    header.DataWindow[3], 0, 0 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(
    outInfo, header.ScalarType, header.NumberOfComponents);
  internals.HeaderValid = true;
  return 1;
}

//------------------------------------------------------------------------------
int vtkOpenEXRReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  if (!output)
  {
    return 0;
  }
  output->Initialize();
  vtkInternals& internals = *this->Internals;
  if (!internals.HeaderValid)
  {
    // RequestInformation already reported the error and set the error code.
    return 1;
  }

  vtkOpenEXRFailure failure;
  vtkOpenEXRCoreFile file;
  vtkOpenEXRHeader header;
  vtkSmartPointer<vtkDataArray> scalars;
  if (file.Open(this->FileName, failure) &&
    ReadHeader(file, this->PartIndex, this->PartName ? this->PartName : "",
      this->Layer ? this->Layer : "", this->MaximumImageBytes, header, failure))
  {
    if (!header.SameLayout(internals.Header))
    {
      failure.Set(vtkErrorCode::FileFormatError, "the file changed after UpdateInformation()");
    }
    else if (ValidateChunks(file, header, this->MaximumImageBytes, failure))
    {
      // Allocate ourselves so that a failed allocation is an error, not an abort.
      const size_t values = static_cast<size_t>(header.Width) * static_cast<size_t>(header.Height) *
        static_cast<size_t>(header.NumberOfComponents);
      void* memory = std::malloc(values * 4);
      if (!memory)
      {
        failure.Set(vtkErrorCode::UnknownError, "out of memory");
      }
      else if (header.ScalarType == VTK_UNSIGNED_INT)
      {
        vtkNew<vtkUnsignedIntArray> array;
        array->SetNumberOfComponents(header.NumberOfComponents);
        array->SetArray(static_cast<unsigned int*>(memory), static_cast<vtkIdType>(values), 0,
          vtkAbstractArray::VTK_DATA_ARRAY_FREE);
        scalars = array;
      }
      else
      {
        vtkNew<vtkFloatArray> array;
        array->SetNumberOfComponents(header.NumberOfComponents);
        array->SetArray(static_cast<float*>(memory), static_cast<vtkIdType>(values), 0,
          vtkAbstractArray::VTK_DATA_ARRAY_FREE);
        scalars = array;
      }
    }
  }

  if (scalars)
  {
    if (header.LuminanceChroma)
    {
      // Validate every chunk with the hardened decoder before the C++ library reads them.
      if (DecodeCore(file, header, nullptr, false, this, failure))
      {
        file.Close();
        ConvertLuminanceChroma(
          this->FileName, header, static_cast<float*>(scalars->GetVoidPointer(0)), failure);
      }
    }
    else
    {
      DecodeCore(file, header, scalars->GetVoidPointer(0), header.ScalarType == VTK_UNSIGNED_INT,
        this, failure);
    }
  }

  if (failure.Code != vtkErrorCode::NoError)
  {
    output->Initialize();
    if (!this->AbortExecute)
    {
      this->SetErrorCode(failure.Code);
      vtkErrorMacro("Cannot read OpenEXR file '" << this->FileName << "': " << failure.Message);
    }
    return 1;
  }

  for (int c = 0; c < header.NumberOfComponents; ++c)
  {
    scalars->SetComponentName(c, header.ComponentNames[c].c_str());
  }
  scalars->SetName("OpenEXRImage");
  output->SetExtent(
    header.DataWindow[0], header.DataWindow[1], header.DataWindow[2], header.DataWindow[3], 0, 0);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->SetOrigin(0.0, 0.0, 0.0);
  output->GetPointData()->SetScalars(scalars);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkOpenEXRReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "PartIndex: " << this->PartIndex << "\n";
  os << indent << "PartName: " << (this->PartName ? this->PartName : "(none)") << "\n";
  os << indent << "Layer: " << (this->Layer ? this->Layer : "(default)") << "\n";
  os << indent << "MaximumImageBytes: " << this->MaximumImageBytes << "\n";
  os << indent << "NumberOfParts: " << this->GetNumberOfParts() << "\n";
  os << indent << "SelectedPartIndex: " << this->SelectedPartIndex << "\n";
  os << indent << "DataWindow: " << this->DataWindow[0] << " " << this->DataWindow[1] << " "
     << this->DataWindow[2] << " " << this->DataWindow[3] << "\n";
  os << indent << "DisplayWindow: " << this->DisplayWindow[0] << " " << this->DisplayWindow[1]
     << " " << this->DisplayWindow[2] << " " << this->DisplayWindow[3] << "\n";
}

// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomCraftedEXR.h"
#include "vtkOpenEXRHuffman.h"

#include <ImathBox.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <ImfTiledOutputFile.h>
#include <half.h>
#include <openexr.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <stdexcept>

namespace vtkBloomCraftedEXR
{
namespace
{
using Bytes = std::vector<unsigned char>;

//------------------------------------------------------------------------------
// Content: smooth light with a little deterministic noise (so that DWA codes real AC
// coefficients), or runs of constant values (so that RLE compresses).
float Value(int x, int y, int c, bool runs)
{
  if (runs)
  {
    return static_cast<float>(((x / 16) + (y / 4) + c) % 5) * 0.5f;
  }
  uint32_t h = static_cast<uint32_t>(x) * 73856093u ^ static_cast<uint32_t>(y) * 19349663u ^
    static_cast<uint32_t>(c) * 83492791u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  const float noise = static_cast<float>(h & 0xffffu) / 65535.0f - 0.5f;
  return 0.6f + 0.5f * std::sin(0.11f * x + c) * std::cos(0.07f * y) + 0.08f * noise;
}

//------------------------------------------------------------------------------
enum class Shape
{
  Scanlines, // A, B, G, R, Z (float), diffuse.{B,G,R}: two colour groups, RLE and UNKNOWN
  Tiles,     // the same channels in four 49x35 tiles (the last a full one)
  YCA,       // Y, RY, BY (2x2), A through Imf::RgbaOutputFile
  Depth      // depth.N (half), depth.Z (float): both UNKNOWN to DWA, and both read
};

struct Valid
{
  std::string Name;
  Shape Form;
  Imf::Compression Codec;
  bool Runs;
  bool Tiled = false; // for Depth: in tiles too
};

const int Width = 97;
const int Height = 70;

void WriteValid(const Valid& valid, const std::string& path)
{
  if (valid.Form == Shape::YCA)
  {
    // Chroma is sampled 2x2: the width must be even.
    const int width = Width - 1;
    std::vector<Imf::Rgba> pixels(static_cast<size_t>(width) * Height);
    for (int y = 0; y < Height; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        Imf::Rgba& p = pixels[static_cast<size_t>(y) * width + x];
        p = Imf::Rgba(Value(x, y, 0, valid.Runs), Value(x, y, 1, valid.Runs),
          Value(x, y, 2, valid.Runs), valid.Runs ? 1.0f : 0.5f + 0.5f * (x > Width / 2));
      }
    }
    Imf::RgbaOutputFile out(path.c_str(),
      Imf::Header(width, Height, 1.0f, Imath::V2f(0, 0), 1.0f, Imf::INCREASING_Y, valid.Codec),
      Imf::WRITE_YCA);
    out.setFrameBuffer(pixels.data(), 1, width);
    out.writePixels(Height);
    return;
  }
  struct Channel
  {
    const char* Name;
    Imf::PixelType Type;
  };
  const Channel colour[] = { { "A", Imf::HALF }, { "B", Imf::HALF }, { "G", Imf::HALF },
    { "R", Imf::HALF }, { "Z", Imf::FLOAT }, { "diffuse.B", Imf::HALF }, { "diffuse.G", Imf::HALF },
    { "diffuse.R", Imf::HALF } };
  const Channel depth[] = { { "depth.N", Imf::HALF }, { "depth.Z", Imf::FLOAT } };
  const bool isDepth = valid.Form == Shape::Depth;
  const Channel* channels = isDepth ? depth : colour;
  const size_t n = isDepth ? std::size(depth) : std::size(colour);
  // One DWAA chunk (32 lines) for the depth files: the damaged chunk is the first one decoded,
  // so OpenEXR's buffers hold no earlier chunk's bytes.
  const int Height = isDepth ? 24 : vtkBloomCraftedEXR::Height;
  Imf::Header header(Width, Height);
  header.compression() = valid.Codec;
  std::vector<std::vector<float>> floats(n);
  std::vector<std::vector<half>> halves(n);
  Imf::FrameBuffer frame;
  for (size_t c = 0; c < n; ++c)
  {
    header.channels().insert(channels[c].Name, Imf::Channel(channels[c].Type));
    floats[c].resize(static_cast<size_t>(Width) * Height);
    for (int y = 0; y < Height; ++y)
    {
      for (int x = 0; x < Width; ++x)
      {
        // Alpha is two flat halves, which DWA's RLE class codes in a few runs.
        floats[c][static_cast<size_t>(y) * Width + x] = c == 0 && !isDepth
          ? (x < Width / 2 ? 1.0f : 0.25f)
          : Value(x, y, static_cast<int>(c), valid.Runs);
      }
    }
    if (channels[c].Type == Imf::HALF)
    {
      halves[c].assign(floats[c].begin(), floats[c].end());
      frame.insert(channels[c].Name,
        Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves[c].data()), sizeof(half),
          sizeof(half) * Width));
    }
    else
    {
      frame.insert(channels[c].Name,
        Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(floats[c].data()), sizeof(float),
          sizeof(float) * Width));
    }
  }
  if (valid.Form == Shape::Tiles || valid.Tiled)
  {
    header.setTileDescription(Imf::TileDescription(49, 35, Imf::ONE_LEVEL));
    Imf::TiledOutputFile out(path.c_str(), header);
    out.setFrameBuffer(frame);
    out.writeTiles(0, out.numXTiles() - 1, 0, out.numYTiles() - 1);
    return;
  }
  Imf::OutputFile out(path.c_str(), header);
  out.setFrameBuffer(frame);
  out.writePixels(Height);
}

Bytes ReadBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

//------------------------------------------------------------------------------
// The chunk that lies last in the file: rewriting it moves no other chunk.
exr_chunk_info_t LastChunk(const std::string& path)
{
  exr_context_t context = nullptr;
  if (exr_start_read(&context, path.c_str(), nullptr) != EXR_ERR_SUCCESS)
  {
    throw std::runtime_error("cannot open " + path);
  }
  exr_storage_t storage = EXR_STORAGE_SCANLINE;
  exr_get_storage(context, 0, &storage);
  exr_attr_box2i_t window{};
  exr_get_data_window(context, 0, &window);
  std::vector<exr_chunk_info_t> chunks;
  if (storage == EXR_STORAGE_TILED)
  {
    uint32_t tx = 0, ty = 0;
    exr_tile_level_mode_t levels{};
    exr_tile_round_mode_t round{};
    exr_get_tile_descriptor(context, 0, &tx, &ty, &levels, &round);
    const int nx = (window.max.x - window.min.x + static_cast<int>(tx)) / static_cast<int>(tx);
    const int ny = (window.max.y - window.min.y + static_cast<int>(ty)) / static_cast<int>(ty);
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        exr_chunk_info_t info{};
        exr_read_tile_chunk_info(context, 0, i, j, 0, 0, &info);
        chunks.push_back(info);
      }
    }
  }
  else
  {
    int32_t lines = 1;
    exr_get_scanlines_per_chunk(context, 0, &lines);
    for (int y = window.min.y; y <= window.max.y; y += lines)
    {
      exr_chunk_info_t info{};
      exr_read_scanline_chunk_info(context, 0, y, &info);
      chunks.push_back(info);
    }
  }
  exr_finish(&context);
  exr_chunk_info_t last{};
  for (const exr_chunk_info_t& info : chunks)
  {
    if (info.data_offset > last.data_offset)
    {
      last = info;
    }
  }
  if (last.packed_size >= last.unpacked_size)
  {
    throw std::runtime_error(path + ": the last chunk is stored uncompressed");
  }
  return last;
}

//------------------------------------------------------------------------------
// zlib, and OpenEXR's byte-wise run-length code (a count c < 0: -c literal bytes follow;
// c >= 0: the next byte c + 1 times).
Bytes Inflate(const unsigned char* data, size_t size, size_t expected)
{
  Bytes out(expected + 64);
  uLongf length = static_cast<uLongf>(out.size());
  if (uncompress(out.data(), &length, data, static_cast<uLong>(size)) != Z_OK)
  {
    throw std::runtime_error("a stream does not inflate");
  }
  out.resize(length);
  return out;
}

Bytes Deflate(const Bytes& data)
{
  Bytes out(compressBound(static_cast<uLong>(data.size())));
  uLongf length = static_cast<uLongf>(out.size());
  compress2(out.data(), &length, data.data(), static_cast<uLong>(data.size()), 9);
  out.resize(length);
  return out;
}

Bytes RunLengthDecode(const Bytes& coded)
{
  Bytes raw;
  for (size_t i = 0; i < coded.size();)
  {
    const int count = static_cast<signed char>(coded[i++]);
    if (count < 0)
    {
      raw.insert(raw.end(), coded.begin() + static_cast<std::ptrdiff_t>(i),
        coded.begin() + static_cast<std::ptrdiff_t>(i) - count);
      i += static_cast<size_t>(-count);
    }
    else
    {
      raw.insert(raw.end(), static_cast<size_t>(count) + 1, coded[i++]);
    }
  }
  return raw;
}

Bytes RunLengthEncodeLiterally(const Bytes& raw)
{
  Bytes coded;
  for (size_t i = 0; i < raw.size(); i += 127)
  {
    const size_t n = std::min<size_t>(127, raw.size() - i);
    coded.push_back(static_cast<unsigned char>(-static_cast<int>(n)));
    coded.insert(coded.end(), raw.begin() + static_cast<std::ptrdiff_t>(i),
      raw.begin() + static_cast<std::ptrdiff_t>(i + n));
  }
  return coded;
}

//------------------------------------------------------------------------------
// One DWA chunk's payload, taken apart (vtkOpenEXRDWA.h has the layout).
struct DWAChunk
{
  uint64_t Word[11] = {};
  Bytes Rules;
  Bytes Unknown, AC, DC, RLE;

  enum
  {
    Version,
    UnknownDecoded,
    UnknownPacked,
    ACPacked,
    DCPacked,
    RLEPacked,
    RLEDeflated,
    RLERaw,
    ACCount,
    DCCount,
    ACCompression
  };

  explicit DWAChunk(const Bytes& payload)
  {
    for (int i = 0; i < 11; ++i)
    {
      for (int b = 7; b >= 0; --b)
      {
        this->Word[i] = (this->Word[i] << 8) | payload[static_cast<size_t>(8 * i + b)];
      }
    }
    size_t at = 88;
    if (this->Word[Version] >= 2)
    {
      const size_t rules = payload[at] | (payload[at + 1] << 8);
      this->Rules.assign(payload.begin() + 88, payload.begin() + 88 + static_cast<long>(rules));
      at += rules;
    }
    Bytes* const parts[] = { &this->Unknown, &this->AC, &this->DC, &this->RLE };
    const int sizes[] = { UnknownPacked, ACPacked, DCPacked, RLEPacked };
    for (int k = 0; k < 4; ++k)
    {
      const uint64_t size = this->Word[sizes[k]];
      parts[k]->assign(
        payload.begin() + static_cast<long>(at), payload.begin() + static_cast<long>(at + size));
      at += size;
    }
  }

  Bytes Pack()
  {
    this->Word[UnknownPacked] = this->Unknown.size();
    this->Word[ACPacked] = this->AC.size();
    this->Word[DCPacked] = this->DC.size();
    this->Word[RLEPacked] = this->RLE.size();
    Bytes out;
    for (uint64_t word : this->Word)
    {
      for (int b = 0; b < 8; ++b)
      {
        out.push_back(static_cast<unsigned char>(word >> (8 * b)));
      }
    }
    for (const Bytes* part : { &this->Rules, &this->Unknown, &this->AC, &this->DC, &this->RLE })
    {
      out.insert(out.end(), part->begin(), part->end());
    }
    return out;
  }
};

//------------------------------------------------------------------------------
// The damage, applied to the last chunk's payload.
enum class Damage
{
  UnknownShort,       // UNKNOWN inflates to 8 bytes fewer, and says so
  UnknownStreamShort, // UNKNOWN inflates to 8 bytes fewer than it says
  RLEShort,           // RLE decodes to 8 bytes fewer, and says so
  DCShort,            // 2 DC values fewer, and says so
  ACShort,            // 8 AC values fewer (deflated), and says so
  StreamShort         // a ZIP(S) or RLE chunk: 16 bytes fewer
};

Bytes Damaged(const Bytes& payload, Damage damage, Imf::Compression codec, size_t unpacked)
{
  if (damage == Damage::StreamShort)
  {
    if (codec == Imf::RLE_COMPRESSION)
    {
      Bytes raw = RunLengthDecode(payload);
      raw.resize(raw.size() - 16);
      return RunLengthEncodeLiterally(raw);
    }
    Bytes raw = Inflate(payload.data(), payload.size(), unpacked);
    raw.resize(raw.size() - 16);
    return Deflate(raw);
  }
  DWAChunk chunk(payload);
  switch (damage)
  {
    case Damage::UnknownShort:
    case Damage::UnknownStreamShort:
    {
      Bytes raw =
        Inflate(chunk.Unknown.data(), chunk.Unknown.size(), chunk.Word[DWAChunk::UnknownDecoded]);
      raw.resize(raw.size() - 8);
      chunk.Unknown = Deflate(raw);
      if (damage == Damage::UnknownShort)
      {
        chunk.Word[DWAChunk::UnknownDecoded] = raw.size();
      }
      break;
    }
    case Damage::RLEShort:
    {
      Bytes raw = RunLengthDecode(
        Inflate(chunk.RLE.data(), chunk.RLE.size(), chunk.Word[DWAChunk::RLEDeflated]));
      raw.resize(raw.size() - 8);
      const Bytes coded = RunLengthEncodeLiterally(raw);
      chunk.RLE = Deflate(coded);
      chunk.Word[DWAChunk::RLERaw] = raw.size();
      chunk.Word[DWAChunk::RLEDeflated] = coded.size();
      break;
    }
    case Damage::DCShort:
    {
      Bytes raw = Inflate(chunk.DC.data(), chunk.DC.size(), 2 * chunk.Word[DWAChunk::DCCount]);
      raw.resize(raw.size() - 4);
      chunk.DC = Deflate(raw);
      chunk.Word[DWAChunk::DCCount] -= 2;
      break;
    }
    case Damage::ACShort:
    {
      // Scanline chunks code AC with static Huffman, tiles with deflate (OpenEXR 3.1).
      std::vector<uint16_t> values;
      std::string error;
      const uint64_t count = chunk.Word[DWAChunk::ACCount];
      if (chunk.Word[DWAChunk::ACCompression] == 1)
      {
        const Bytes raw = Inflate(chunk.AC.data(), chunk.AC.size(), 2 * count);
        for (size_t i = 0; i + 1 < raw.size(); i += 2)
        {
          values.push_back(static_cast<uint16_t>(raw[i] | (raw[i + 1] << 8)));
        }
      }
      else if (!vtkOpenEXRHuffmanDecode(chunk.AC.data(), chunk.AC.size(), count, values, error))
      {
        throw std::runtime_error("the AC stream does not decode: " + error);
      }
      values.resize(values.size() - 8);
      Bytes raw;
      for (uint16_t v : values)
      {
        raw.push_back(static_cast<unsigned char>(v & 0xff));
        raw.push_back(static_cast<unsigned char>(v >> 8));
      }
      chunk.AC = Deflate(raw);
      chunk.Word[DWAChunk::ACCount] = values.size();
      chunk.Word[DWAChunk::ACCompression] = 1; // deflate
      break;
    }
    default:
      break;
  }
  return chunk.Pack();
}

//------------------------------------------------------------------------------
Bytes Craft(const std::string& validPath, Damage damage, Imf::Compression codec)
{
  const Bytes file = ReadBytes(validPath);
  const exr_chunk_info_t last = LastChunk(validPath);
  const size_t begin = static_cast<size_t>(last.data_offset);
  const Bytes payload(file.begin() + static_cast<long>(begin),
    file.begin() + static_cast<long>(begin + last.packed_size));
  const Bytes damaged = Damaged(payload, damage, codec, static_cast<size_t>(last.unpacked_size));
  Bytes out(file.begin(), file.begin() + static_cast<long>(begin - 4));
  const uint32_t size = static_cast<uint32_t>(damaged.size());
  for (int b = 0; b < 4; ++b)
  {
    out.push_back(static_cast<unsigned char>(size >> (8 * b)));
  }
  out.insert(out.end(), damaged.begin(), damaged.end());
  return out;
}

struct Recipe
{
  const char* Name;
  Valid From;
  Damage Harm;
  const char* Description;
};

std::vector<Recipe> Recipes()
{
  const Valid dwaa{ "dwaa", Shape::Scanlines, Imf::DWAA_COMPRESSION, false };
  const Valid dwab{ "dwab", Shape::Scanlines, Imf::DWAB_COMPRESSION, false };
  const Valid tiled{ "dwaa-tiled", Shape::Tiles, Imf::DWAA_COMPRESSION, false };
  const Valid yca{ "dwaa-yca", Shape::YCA, Imf::DWAA_COMPRESSION, false };
  const Valid depthA{ "dwaa-depth", Shape::Depth, Imf::DWAA_COMPRESSION, false };
  const Valid depthB{ "dwab-depth", Shape::Depth, Imf::DWAB_COMPRESSION, false };
  const Valid depthTiled{ "dwaa-depth-tiled", Shape::Depth, Imf::DWAA_COMPRESSION, false, true };
  const Valid rle{ "rle", Shape::Scanlines, Imf::RLE_COMPRESSION, true };
  const Valid zips{ "zips", Shape::Scanlines, Imf::ZIPS_COMPRESSION, false };
  const Valid zip{ "zip", Shape::Scanlines, Imf::ZIP_COMPRESSION, false };
  const Valid rleYca{ "rle-yca", Shape::YCA, Imf::RLE_COMPRESSION, true };
  const Valid zipYca{ "zip-yca", Shape::YCA, Imf::ZIP_COMPRESSION, false };
  const Valid zipTiled{ "zip-tiled", Shape::Tiles, Imf::ZIP_COMPRESSION, false };
  return {
    { "dwaa-unknown-short.exr", depthA, Damage::UnknownShort,
      "DWAA: the UNKNOWN stream (depth.N, depth.Z) and its stated size 8 bytes short of the "
      "channel list" },
    { "dwaa-unknown-stream-short.exr", depthA, Damage::UnknownStreamShort,
      "DWAA: the UNKNOWN stream inflates to 8 bytes fewer than its stated size" },
    { "dwaa-rgbz-unknown-short.exr", dwaa, Damage::UnknownShort,
      "DWAA: the UNKNOWN stream (Z, beside R, G, B, A) 8 bytes short" },
    { "dwaa-rle-short.exr", dwaa, Damage::RLEShort,
      "DWAA: the RLE stream (A) and its raw size 8 bytes short" },
    { "dwaa-dc-short.exr", dwaa, Damage::DCShort,
      "DWAA: two DC values fewer than the lossy channels' blocks" },
    { "dwaa-ac-short.exr", dwaa, Damage::ACShort,
      "DWAA: the AC stream (deflated) 8 values short of what the blocks read" },
    { "dwab-unknown-short.exr", depthB, Damage::UnknownShort, "DWAB: UNKNOWN 8 bytes short" },
    { "dwab-unknown-stream-short.exr", depthB, Damage::UnknownStreamShort,
      "DWAB: UNKNOWN inflates short of its stated size" },
    { "dwab-rle-short.exr", dwab, Damage::RLEShort, "DWAB: RLE 8 bytes short" },
    { "dwab-dc-short.exr", dwab, Damage::DCShort, "DWAB: two DC values short" },
    { "dwab-ac-short.exr", dwab, Damage::ACShort, "DWAB: 8 AC values short" },
    { "dwaa-tiled-unknown-short.exr", depthTiled, Damage::UnknownShort,
      "tiled DWAA: UNKNOWN 8 bytes short" },
    { "dwaa-tiled-rle-short.exr", tiled, Damage::RLEShort, "tiled DWAA: RLE 8 bytes short" },
    { "dwaa-tiled-dc-short.exr", tiled, Damage::DCShort, "tiled DWAA: two DC values short" },
    { "dwaa-tiled-ac-short.exr", tiled, Damage::ACShort, "tiled DWAA: 8 AC values short" },
    { "dwaa-yca-rle-short.exr", yca, Damage::RLEShort,
      "luminance/chroma DWAA: the RLE stream (A) 8 bytes short" },
    { "dwaa-yca-dc-short.exr", yca, Damage::DCShort, "luminance/chroma DWAA: two DC values short" },
    { "dwaa-yca-ac-short.exr", yca, Damage::ACShort,
      "luminance/chroma DWAA: 8 AC values short (Y, RY and BY decode apart)" },
    { "rle-short.exr", rle, Damage::StreamShort, "RLE: a chunk 16 bytes short" },
    { "zips-short.exr", zips, Damage::StreamShort, "ZIPS: a chunk inflates 16 bytes short" },
    { "zip-short.exr", zip, Damage::StreamShort, "ZIP: a chunk inflates 16 bytes short" },
    { "zip-tiled-short.exr", zipTiled, Damage::StreamShort,
      "tiled ZIP: a tile inflates 16 bytes short" },
    { "rle-yca-short.exr", rleYca, Damage::StreamShort,
      "luminance/chroma RLE: a chunk 16 bytes short" },
    { "zip-yca-short.exr", zipYca, Damage::StreamShort,
      "luminance/chroma ZIP: a chunk inflates 16 bytes short" },
  };
}
}

//------------------------------------------------------------------------------
std::vector<File> MakeValid(const std::string& scratch)
{
  std::filesystem::create_directories(scratch);
  std::vector<File> files;
  std::vector<std::string> seen;
  for (const Recipe& recipe : Recipes())
  {
    if (std::find(seen.begin(), seen.end(), recipe.From.Name) != seen.end())
    {
      continue;
    }
    seen.push_back(recipe.From.Name);
    const std::string path = scratch + "/" + recipe.From.Name + ".exr";
    WriteValid(recipe.From, path);
    files.push_back(File{ recipe.From.Name + ".exr", "valid", ReadBytes(path) });
  }
  return files;
}

//------------------------------------------------------------------------------
std::vector<File> MakeAll(const std::string& scratch)
{
  std::filesystem::create_directories(scratch);
  std::vector<File> files;
  for (const Recipe& recipe : Recipes())
  {
    const std::string path = scratch + "/" + recipe.From.Name + ".exr";
    WriteValid(recipe.From, path);
    try
    {
      files.push_back(
        File{ recipe.Name, recipe.Description, Craft(path, recipe.Harm, recipe.From.Codec) });
    }
    catch (const std::exception& e)
    {
      throw std::runtime_error(std::string(recipe.Name) + ": " + e.what());
    }
  }
  return files;
}

//------------------------------------------------------------------------------
std::vector<std::string> WriteAll(const std::vector<File>& files, const std::string& directory)
{
  std::filesystem::create_directories(directory);
  std::vector<std::string> paths;
  for (const File& file : files)
  {
    const std::string path = directory + "/" + file.Name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(file.Bytes.data()),
      static_cast<std::streamsize>(file.Bytes.size()));
    paths.push_back(path);
  }
  return paths;
}
}

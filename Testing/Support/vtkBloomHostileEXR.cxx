// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBloomHostileEXR.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace vtkBloomHostileEXR
{
namespace
{
// The OpenEXR layout, as docs/OpenEXRFileLayout.rst of the OpenEXR project describes it.
constexpr uint32_t Tiled = 0x200, LongNames = 0x400, NonImage = 0x800, MultiPart = 0x1000;
enum PixelType : int32_t
{
  UINT = 0,
  HALF = 1,
  FLOAT = 2
};
const char* const CompressionNames[10] = { "none", "rle", "zips", "zip", "piz", "pxr24", "b44",
  "b44a", "dwaa", "dwab" };
const int LinesPerChunk[10] = { 1, 1, 1, 16, 32, 16, 32, 32, 32, 256 };

// Little-endian byte sink.
struct Bytes
{
  std::vector<unsigned char> B;

  Bytes& U8(uint8_t v)
  {
    this->B.push_back(v);
    return *this;
  }
  Bytes& U32(uint32_t v)
  {
    for (int i = 0; i < 4; ++i)
    {
      this->B.push_back(static_cast<unsigned char>(v >> (8 * i)));
    }
    return *this;
  }
  Bytes& I32(int32_t v) { return this->U32(static_cast<uint32_t>(v)); }
  Bytes& U64(uint64_t v)
  {
    for (int i = 0; i < 8; ++i)
    {
      this->B.push_back(static_cast<unsigned char>(v >> (8 * i)));
    }
    return *this;
  }
  Bytes& F32(float v)
  {
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    return this->U32(bits);
  }
  Bytes& Str(const std::string& s)
  {
    this->B.insert(this->B.end(), s.begin(), s.end());
    this->B.push_back(0);
    return *this;
  }
  Bytes& Append(const Bytes& other)
  {
    this->B.insert(this->B.end(), other.B.begin(), other.B.end());
    return *this;
  }
  Bytes& Zeros(size_t n)
  {
    this->B.insert(this->B.end(), n, 0);
    return *this;
  }
  Bytes& Attribute(const std::string& name, const std::string& type, const Bytes& value)
  {
    this->Str(name).Str(type).I32(static_cast<int32_t>(value.B.size()));
    return this->Append(value);
  }
  size_t Size() const { return this->B.size(); }
};

struct Channel
{
  std::string Name;
  int32_t Type = HALF;
  int32_t XSampling = 1;
  int32_t YSampling = 1;
};

std::vector<Channel> RGB(int32_t type = HALF)
{
  // Channel lists are sorted by name.
  return { { "B", type }, { "G", type }, { "R", type } };
}

// One part's header attributes (without the terminating zero).
struct Part
{
  std::vector<Channel> Channels = RGB();
  int Compression = 0;
  int32_t Window[4] = { 0, 0, 0, 0 }; // xmin, ymin, xmax, ymax
  bool IsTiled = false;
  uint32_t TileX = 64, TileY = 64;
  uint8_t LevelMode = 0; // 0 one level, 1 mipmap, 2 ripmap
  std::string Name;      // multi-part and deep parts
  std::string Type;      // "scanlineimage", "tiledimage", "deepscanline", "deeptile"
  int64_t ChunkCount = -1;
  Bytes Extra; // more attributes, written last

  Bytes Header() const
  {
    Bytes list;
    for (const Channel& c : this->Channels)
    {
      list.Str(c.Name).I32(c.Type).U8(0).Zeros(3).I32(c.XSampling).I32(c.YSampling);
    }
    list.U8(0);
    Bytes box;
    box.I32(this->Window[0]).I32(this->Window[1]).I32(this->Window[2]).I32(this->Window[3]);
    Bytes h;
    h.Attribute("channels", "chlist", list);
    h.Attribute("compression", "compression", Bytes().U8(static_cast<uint8_t>(this->Compression)));
    h.Attribute("dataWindow", "box2i", box);
    // A modest display window: the data window is what the reader allocates.
    h.Attribute("displayWindow", "box2i", Bytes().I32(0).I32(0).I32(1919).I32(1079));
    h.Attribute("lineOrder", "lineOrder", Bytes().U8(0));
    h.Attribute("pixelAspectRatio", "float", Bytes().F32(1.0f));
    h.Attribute("screenWindowCenter", "v2f", Bytes().F32(0.0f).F32(0.0f));
    h.Attribute("screenWindowWidth", "float", Bytes().F32(1.0f));
    if (this->IsTiled)
    {
      h.Attribute(
        "tiles", "tiledesc", Bytes().U32(this->TileX).U32(this->TileY).U8(this->LevelMode));
    }
    if (!this->Name.empty())
    {
      h.Attribute("name", "string", this->NameValue());
    }
    if (!this->Type.empty())
    {
      Bytes type;
      type.B.assign(this->Type.begin(), this->Type.end());
      h.Attribute("type", "string", type);
      if (this->Type.compare(0, 4, "deep") == 0)
      {
        h.Attribute("version", "int", Bytes().I32(1));
        h.Attribute("maxSamplesPerPixel", "int", Bytes().I32(1 << 30));
      }
    }
    if (this->ChunkCount >= 0)
    {
      h.Attribute("chunkCount", "int", Bytes().I32(static_cast<int32_t>(this->ChunkCount)));
    }
    return h.Append(this->Extra);
  }

  Bytes NameValue() const
  {
    Bytes name;
    name.B.assign(this->Name.begin(), this->Name.end());
    return name;
  }

  int64_t Width() const { return int64_t(this->Window[2]) - this->Window[0] + 1; }
  int64_t Height() const { return int64_t(this->Window[3]) - this->Window[1] + 1; }
};

uint32_t VersionField(uint32_t flags)
{
  return 2u | flags;
}

// A single-part file: magic, version, header, offset table, chunks. Each chunk is its
// coordinates, `packedSize` and `payload` bytes; the table points at the chunks unless
// `offsetOf` says otherwise (given the chunk index and its true offset).
template <typename Offset>
File SinglePart(const std::string& name, const std::string& description, const Part& part,
  uint32_t flags, int32_t packedSize, size_t payload, Offset offsetOf)
{
  Bytes file;
  // Deep parts say "tiled" in their type attribute, not in the version field.
  const bool tiledFlag = part.IsTiled && (flags & NonImage) == 0;
  file.U32(20000630).U32(VersionField(flags | (tiledFlag ? Tiled : 0)));
  file.Append(part.Header()).U8(0);
  // Chunks of level 0 only: enough for every reader to reach them first.
  std::vector<std::pair<int32_t, int32_t>> coordinates;
  if (part.IsTiled)
  {
    const int64_t nx = (part.Width() + part.TileX - 1) / part.TileX;
    const int64_t ny = (part.Height() + part.TileY - 1) / part.TileY;
    for (int64_t j = 0; j < ny && coordinates.size() < 64; ++j)
    {
      for (int64_t i = 0; i < nx && coordinates.size() < 64; ++i)
      {
        coordinates.emplace_back(static_cast<int32_t>(i), static_cast<int32_t>(j));
      }
    }
  }
  else
  {
    const int lines = LinesPerChunk[part.Compression];
    for (int64_t y = 0; y < part.Height() && coordinates.size() < 64; y += lines)
    {
      coordinates.emplace_back(0, static_cast<int32_t>(part.Window[1] + y));
    }
  }
  const size_t chunkBytes = (part.IsTiled ? 20 : 8) + payload;
  const size_t first = file.Size() + 8 * coordinates.size();
  for (size_t c = 0; c < coordinates.size(); ++c)
  {
    file.U64(offsetOf(c, static_cast<uint64_t>(first + c * chunkBytes)));
  }
  for (const auto& xy : coordinates)
  {
    if (part.IsTiled)
    {
      file.I32(xy.first).I32(xy.second).I32(0).I32(0);
    }
    else
    {
      file.I32(xy.second);
    }
    file.I32(packedSize).Zeros(payload);
  }
  return { name, description, file.B };
}

File SinglePart(const std::string& name, const std::string& description, const Part& part,
  int32_t packedSize, size_t payload)
{
  return SinglePart(name, description, part, 0, packedSize, payload,
    [](size_t, uint64_t offset) { return offset; });
}

Part Window(Part part, int32_t xmin, int32_t ymin, int32_t xmax, int32_t ymax)
{
  part.Window[0] = xmin;
  part.Window[1] = ymin;
  part.Window[2] = xmax;
  part.Window[3] = ymax;
  return part;
}
}

//------------------------------------------------------------------------------
std::vector<File> MakeAll()
{
  std::vector<File> files;

  // Per compression: a huge data window whose chunks hold 64 bytes each, as scanlines and as
  // one tile (below the default pixel limit, so only the chunk bound can refuse it).
  for (int c = 0; c < 10; ++c)
  {
    const std::string compression = CompressionNames[c];
    Part scan;
    scan.Compression = c;
    scan = Window(scan, 0, 0, 99999, LinesPerChunk[c] * 8 - 1);
    files.push_back(SinglePart("huge-scanlines-" + compression + ".exr",
      "100000-pixel rows, 8 chunks of 64 compressed bytes each", scan, 64, 64));

    Part tile;
    tile.Compression = c;
    tile.IsTiled = true;
    tile.TileX = tile.TileY = 16000;
    tile = Window(tile, 0, 0, 15999, 15999);
    files.push_back(SinglePart("huge-tile-" + compression + ".exr",
      "one 16000x16000 RGB tile of 64 compressed bytes", tile, 64, 64));

    Part y;
    y.Compression = c;
    y.Channels = { { "Y", FLOAT } };
    y.IsTiled = true;
    y.TileX = y.TileY = 16384;
    y = Window(y, 0, 0, 16383, 16383);
    files.push_back(SinglePart("huge-tile-at-limit-" + compression + ".exr",
      "one 16384x16384 float tile (exactly the default pixel limit) of 1 byte", y, 1, 1));

    Part empty = scan;
    files.push_back(SinglePart("zero-size-chunks-" + compression + ".exr",
      "huge rows whose chunks claim 0 compressed bytes", empty, 0, 0));
  }

  Part small;
  small = Window(small, 0, 0, 15, 15);
  // Tables that point where no chunk is. The chunks themselves are left out: with them in the
  // file, OpenEXR rebuilds a damaged table by scanning, and the file reads correctly.
  auto outside = [&](const std::string& name, const std::string& what, uint64_t offset)
  {
    File file =
      SinglePart(name, what, small, 0, 96, 96, [offset](size_t, uint64_t) { return offset; });
    file.Bytes.resize(file.Bytes.size() - 16 * (8 + 96));
    files.push_back(file);
  };
  outside("offsets-past-end.exr", "every chunk offset is past the end of the file", 1u << 30);
  outside("offsets-max.exr", "every chunk offset is 2^64 - 1", ~uint64_t(0));
  outside("offsets-zero.exr", "every chunk offset is 0 (the magic number)", 0);
  outside("offsets-into-header.exr", "every chunk offset points into the header", 12);
  files.push_back(SinglePart("offsets-same-chunk.exr", "every offset points at the first chunk",
    small, 0, 96, 96, [](size_t c, uint64_t offset) { return offset - c * (8 + 96); }));
  files.push_back(SinglePart("packed-size-past-end.exr", "chunks claim 2^31 - 1 compressed bytes",
    small, 0, 0x7fffffff, 96, [](size_t, uint64_t offset) { return offset; }));
  files.push_back(SinglePart("packed-size-negative.exr", "chunks claim -1 compressed bytes", small,
    0, -1, 96, [](size_t, uint64_t offset) { return offset; }));
  {
    File f = SinglePart("truncated-offset-table.exr", "the file ends inside the offset table",
      Window(small, 0, 0, 15, 99999), 96, 96);
    Part header = Window(small, 0, 0, 15, 99999);
    Bytes prefix;
    prefix.U32(20000630).U32(VersionField(0)).Append(header.Header()).U8(0).Zeros(40);
    f.Bytes = prefix.B;
    files.push_back(f);
  }

  // Windows that no image can have.
  files.push_back(
    SinglePart("window-whole-int-range.exr", "data window (-2^31, -2^31) - (2^31 - 1, 2^31 - 1)",
      Window(small, INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX), 96, 96));
  files.push_back(SinglePart(
    "window-inverted.exr", "data window with min > max", Window(small, 100, 100, 0, 0), 96, 96));
  files.push_back(SinglePart("window-one-row-2g-wide.exr", "a 2^31 - 1 pixel wide row",
    Window(small, 0, 0, INT32_MAX - 1, 0), 96, 96));

  // Attributes whose sizes claim gigabytes.
  {
    Part a = small;
    a.Extra.Str("comments").Str("string").I32(0x7ffffff0).Str("abc");
    files.push_back(
      SinglePart("attribute-size-2g.exr", "a string attribute of 2^31 bytes", a, 96, 96));
    Part b = small;
    b.Extra.Str("preview").Str("preview").I32(24).U32(65535).U32(65535).Zeros(16);
    files.push_back(
      SinglePart("preview-65535x65535.exr", "a 65535x65535 preview image", b, 96, 96));
    Part c = small;
    c.Extra.Str("multiView").Str("stringvector").I32(8).I32(0x7ffffff0).Str("abc");
    files.push_back(
      SinglePart("stringvector-2g.exr", "a string vector entry of 2^31 bytes", c, 96, 96));
  }

  // Headers that reach known flaws of OpenEXR 3.1 (docs/openexr.md): a luminance/chroma layer
  // with an empty view list (Imf::RgbaInputFile reads its first view), and PIZ chunks of 2^29
  // pixels, where OpenEXR 3.1's PIZ decoders overflow (CVE-2026-34588) once a caller raises
  // the pixel limit.
  {
    Part views = Window(small, 0, 0, 63, 1);
    views.Channels = { { "x.BY", HALF, 2, 2 }, { "x.RY", HALF, 2, 2 }, { "x.Y", HALF } };
    views.Extra.Str("multiView").Str("stringvector").I32(0);
    files.push_back(SinglePart("multiview-empty-yca.exr",
      "a luminance/chroma layer with a multiView attribute that names no view", views, 256, 256));
    Part piz = Window(small, 0, 0, (1 << 24) - 1, 31);
    piz.Compression = 4;
    files.push_back(SinglePart("piz-2^29-pixel-chunk.exr",
      "one PIZ chunk of 2^24 x 32 pixels (2^29: OpenEXR 3.1's PIZ overflow)", piz, 64, 64));
  }

  // Tiled layouts.
  {
    Part tiny = Window(small, 0, 0, (1 << 30) - 1, 0);
    tiny.IsTiled = true;
    tiny.TileX = tiny.TileY = 1;
    for (uint8_t mode : { uint8_t(0), uint8_t(1), uint8_t(2) })
    {
      tiny.LevelMode = mode;
      const char* names[3] = { "one-level", "mipmap", "ripmap" };
      files.push_back(SinglePart(std::string("tiles-1x1-") + names[mode] + "-2^30-wide.exr",
        "2^30 one-pixel tiles in a few hundred bytes", tiny, 96, 96));
    }
    Part giantTile = small;
    giantTile.IsTiled = true;
    giantTile.TileX = giantTile.TileY = 0x7fffffff;
    files.push_back(
      SinglePart("tile-size-2^31.exr", "tiles of 2^31 - 1 pixels on a side", giantTile, 96, 96));
    Part mip = Window(small, 0, 0, 65535, 65535);
    mip.IsTiled = true;
    mip.TileX = mip.TileY = 8192;
    mip.LevelMode = 1;
    mip.Compression = 3;
    files.push_back(SinglePart("mipmap-huge-zip.exr",
      "a 65536x65536 mip-mapped ZIP image in 64 tiles of 64 bytes", mip, 64, 64));
  }

  // Channels.
  {
    Part many = Window(small, 0, 0, 4095, 4095);
    many.Compression = 9;
    many.Channels.clear();
    for (int i = 0; i < 2000; ++i)
    {
      many.Channels.push_back({ "c" + std::to_string(1000000 + i), FLOAT });
    }
    files.push_back(SinglePart(
      "channels-2000-dwab.exr", "2000 float channels of a 4096x4096 DWAB image", many, 64, 64));
    Part sub = Window(small, 0, 0, 1 << 20, 1 << 10);
    sub.Compression = 3;
    sub.Channels = { { "R", HALF, 1 << 20, 1 << 10 } };
    files.push_back(
      SinglePart("subsampled-2^20.exr", "a channel sampled every 2^20 pixels", sub, 64, 64));
    Part lc = Window(small, 0, 0, 15999, 15999);
    lc.Compression = 3;
    lc.Channels = { { "BY", HALF, 2, 2 }, { "RY", HALF, 2, 2 }, { "Y", HALF } };
    files.push_back(SinglePart("luminance-chroma-huge.exr",
      "a 16000x16000 luminance/chroma image in 8 chunks of 64 bytes", lc, 64, 64));
    Part uints = Window(small, 0, 0, 99999, 127);
    uints.Compression = 3;
    uints.Channels = { { "id", UINT } };
    files.push_back(
      SinglePart("uint-huge-zip.exr", "100000-pixel UINT rows of 64 bytes each", uints, 64, 64));
  }

  // Deep parts, long names, multi-part files.
  {
    Part deep = Window(small, 0, 0, 99999, 99999);
    deep.Compression = 2;
    deep.Type = "deepscanline";
    deep.ChunkCount = 100000;
    files.push_back(SinglePart("deep-scanline-huge.exr", "a 100000x100000 deep scanline image",
      deep, NonImage, 64, 64, [](size_t, uint64_t offset) { return offset; }));
    deep.Type = "deeptile";
    deep.IsTiled = true;
    deep.TileX = deep.TileY = 100000;
    deep.ChunkCount = 1;
    files.push_back(SinglePart("deep-tile-huge.exr", "a 100000x100000 deep tile", deep, NonImage,
      64, 64, [](size_t, uint64_t offset) { return offset; }));

    Part longNames = Window(small, 0, 0, 99999, 15);
    longNames.Compression = 3;
    longNames.Channels = { { std::string(250, 'L') + ".R", FLOAT } };
    files.push_back(SinglePart("long-names-huge.exr", "a 250-character channel name, huge rows",
      longNames, LongNames, 64, 64, [](size_t, uint64_t offset) { return offset; }));
  }
  {
    // Two parts: a valid tiny first part, and a second part whose header claims 2^30 chunks.
    Part a = small;
    a.Name = "small";
    a.Type = "scanlineimage";
    a.ChunkCount = 16;
    Part b = Window(small, 0, 0, 65535, (1 << 30) - 1);
    b.Name = "huge";
    b.Type = "scanlineimage";
    b.ChunkCount = 1 << 30;
    Bytes file;
    file.U32(20000630).U32(VersionField(MultiPart));
    file.Append(a.Header()).U8(0).Append(b.Header()).U8(0).U8(0);
    const uint64_t first = file.Size() + 8 * 16 + 8 * 4;
    for (int i = 0; i < 16; ++i)
    {
      file.U64(first + static_cast<uint64_t>(i) * (12 + 96));
    }
    for (int i = 0; i < 4; ++i)
    {
      file.U64(first);
    }
    for (int i = 0; i < 16; ++i)
    {
      file.I32(0).I32(i).I32(96).Zeros(96);
    }
    files.push_back({ "multipart-2^30-chunks.exr",
      "a multi-part file whose second part claims 2^30 chunks", file.B });

    Part c = Window(small, 0, 0, 99999, 127);
    c.Name = "wide";
    c.Type = "scanlineimage";
    c.Compression = 3;
    c.ChunkCount = 8;
    Bytes wide;
    wide.U32(20000630).U32(VersionField(MultiPart));
    wide.Append(c.Header()).U8(0).U8(0);
    const uint64_t start = wide.Size() + 8 * 8;
    for (int i = 0; i < 8; ++i)
    {
      wide.U64(start + static_cast<uint64_t>(i) * (12 + 64));
    }
    for (int i = 0; i < 8; ++i)
    {
      wide.I32(0).I32(16 * i).I32(64).Zeros(64);
    }
    files.push_back({ "multipart-huge-zip.exr",
      "a multi-part file of one 100000x128 ZIP part in 8 chunks of 64 bytes", wide.B });
  }
  return files;
}

//------------------------------------------------------------------------------
void PrintTo(const File& file, std::ostream* os)
{
  *os << file.Name << " (" << file.Description << ", " << file.Bytes.size() << " bytes)";
}

//------------------------------------------------------------------------------
std::vector<std::string> WriteAll(const std::string& directory)
{
  namespace fs = std::filesystem;
  fs::create_directories(directory);
  std::vector<std::string> paths;
  for (const File& file : MakeAll())
  {
    const std::string path = (fs::path(directory) / file.Name).string();
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(file.Bytes.data()),
      static_cast<std::streamsize>(file.Bytes.size()));
    paths.push_back(path);
  }
  return paths;
}
}

// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// VTK-HeaderTest-Exclude: vtkOpenEXRDWA.cxx
#include "vtkOpenEXRDWA.h"
#include "vtkOpenEXRBytes.h"
#include "vtkOpenEXRHuffman.h"

#include "vtkErrorCode.h"
#include "vtkSMPTools.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <map>
#include <mutex>
#include <sstream>

namespace
{
//------------------------------------------------------------------------------
// The chunk's header: eleven little-endian 64-bit words, in this order.
enum HeaderWord
{
  Version,
  UnknownDecodedSize,
  UnknownPackedSize,
  ACPackedSize,
  DCPackedSize,
  RLEPackedSize,
  RLEDeflatedSize, // the run-length coded bytes, after inflation
  RLERawSize,      // the bytes after run-length decoding
  ACCount,
  DCCount,
  ACCompression,
  HeaderWords
};
constexpr uint64_t HeaderBytes = HeaderWords * 8;

enum Scheme
{
  Unknown = 0,
  LossyDCT = 1,
  RLE = 2,
  Schemes = 3
};

enum ACCoding
{
  StaticHuffman = 0,
  Deflate = 1
};

//------------------------------------------------------------------------------
// A rule that classes a channel by the part of its name after the last '.', and its type.
struct Rule
{
  std::string Suffix;
  int Scheme = Unknown;
  int Type = 0;         // exr_pixel_type_t
  int ColourIndex = -1; // 0, 1, 2: R, G, B of a group converted to Y'CbCr together
  bool CaseInsensitive = false;

  bool Matches(const std::string& suffix, int type) const
  {
    if (type != this->Type || suffix.size() != this->Suffix.size())
    {
      return false;
    }
    // As OpenEXR compares: only the channel's suffix is lowered, so a case-insensitive rule
    // with capitals (possible only in a file's own rules) matches nothing.
    for (size_t i = 0; i < suffix.size(); ++i)
    {
      const unsigned char a = static_cast<unsigned char>(suffix[i]);
      if ((this->CaseInsensitive ? std::tolower(a) : a) !=
        static_cast<unsigned char>(this->Suffix[i]))
      {
        return false;
      }
    }
    return true;
  }
};

// Chunks of version 0 and 1 carry no rules: these are the ones their writers used.
std::vector<Rule> LegacyRules()
{
  std::vector<Rule> rules;
  const struct
  {
    const char* Suffix;
    int Scheme;
    int ColourIndex;
  } named[] = { { "r", LossyDCT, 0 }, { "red", LossyDCT, 0 }, { "g", LossyDCT, 1 },
    { "grn", LossyDCT, 1 }, { "green", LossyDCT, 1 }, { "b", LossyDCT, 2 }, { "blu", LossyDCT, 2 },
    { "blue", LossyDCT, 2 }, { "y", LossyDCT, -1 }, { "by", LossyDCT, -1 }, { "ry", LossyDCT, -1 },
    { "a", RLE, -1 } };
  for (const auto& entry : named)
  {
    for (int type : { EXR_PIXEL_UINT, EXR_PIXEL_HALF, EXR_PIXEL_FLOAT })
    {
      if (entry.Scheme == LossyDCT && type == EXR_PIXEL_UINT)
      {
        continue;
      }
      rules.push_back(Rule{ entry.Suffix, entry.Scheme, type, entry.ColourIndex, true });
    }
  }
  return rules;
}

//------------------------------------------------------------------------------
// Version 2 rules: a 16-bit size (itself included), then per rule a NUL-terminated suffix of
// at most 255 characters, a byte (colour index + 1 << 4 | scheme << 2 | case-insensitive) and
// the pixel type. Anything OpenEXR would refuse, or read differently, is refused.
bool ParseRules(const uint8_t* data, uint64_t available, std::vector<Rule>& rules,
  uint64_t& ruleBytes, std::string& error)
{
  if (available < 2)
  {
    error = "its channel rules are truncated";
    return false;
  }
  ruleBytes = static_cast<uint64_t>(data[0]) | static_cast<uint64_t>(data[1]) << 8;
  if (ruleBytes < 2 || ruleBytes > available)
  {
    error = "its channel rules claim " + std::to_string(ruleBytes) + " bytes";
    return false;
  }
  uint64_t at = 2;
  while (at < ruleBytes)
  {
    const uint8_t* begin = data + at;
    const uint64_t left = ruleBytes - at;
    const uint8_t* end = std::find(begin, begin + std::min<uint64_t>(left, 256), uint8_t(0));
    const uint64_t length = static_cast<uint64_t>(end - begin);
    if (length >= 255 || length + 3 > left)
    {
      error = "a channel rule is truncated";
      return false;
    }
    Rule rule;
    rule.Suffix.assign(reinterpret_cast<const char*>(begin), static_cast<size_t>(length));
    const uint8_t flags = begin[length + 1];
    const uint8_t type = begin[length + 2];
    rule.ColourIndex = (flags >> 4) - 1;
    rule.Scheme = (flags >> 2) & 3;
    rule.CaseInsensitive = (flags & 1) != 0;
    rule.Type = type;
    if (rule.ColourIndex > 2 || rule.Scheme >= Schemes || type > EXR_PIXEL_FLOAT)
    {
      error = "a channel rule is invalid";
      return false;
    }
    rules.push_back(rule);
    at += length + 3;
  }
  return true;
}

//------------------------------------------------------------------------------
// Samples of a channel sampled every `s` pixels in [a, b]: multiples of s (floor division).
int64_t Samples(int s, int64_t a, int64_t b)
{
  auto floorDiv = [](int64_t x, int64_t d) { return x >= 0 ? x / d : -((-x + d - 1) / d); };
  return floorDiv(b, s) - floorDiv(a - 1, s);
}

int64_t BytesOf(int type)
{
  return type == EXR_PIXEL_HALF ? 2 : 4;
}

//------------------------------------------------------------------------------
// What the channel list requires of one chunk's streams, under the chunk's rules.
struct Requirements
{
  uint64_t UnknownBytes = 0;
  uint64_t RLEBytes = 0;
  uint64_t Blocks = 0; // 8x8 blocks of lossy channels: one DC value each, 1 to 63 AC values
  int LossyGroups = 0; // colour groups and lone lossy channels: one DCT decoder each
};

bool Require(const vtkOpenEXRHeader& header, const std::vector<Rule>& rules, int startX, int startY,
  int width, int height, Requirements& need, std::string& error)
{
  const size_t n = header.Channels.size();
  std::vector<int> scheme(n, Unknown);
  std::map<std::string, std::array<int, 3>> groups;
  for (size_t c = 0; c < n; ++c)
  {
    const vtkOpenEXRChannel& channel = header.Channels[c];
    const size_t dot = channel.Name.find_last_of('.');
    const std::string prefix = dot == std::string::npos ? "" : channel.Name.substr(0, dot);
    const std::string suffix =
      dot == std::string::npos ? channel.Name : channel.Name.substr(dot + 1);
    auto group = groups.emplace(prefix, std::array<int, 3>{ -1, -1, -1 }).first;
    // Every rule that matches applies in turn: the last one decides.
    for (const Rule& rule : rules)
    {
      if (rule.Matches(suffix, channel.Type))
      {
        scheme[c] = rule.Scheme;
        if (rule.ColourIndex >= 0)
        {
          group->second[static_cast<size_t>(rule.ColourIndex)] = static_cast<int>(c);
        }
      }
    }
  }

  auto size = [&](size_t c, int64_t& w, int64_t& h)
  {
    const vtkOpenEXRChannel& channel = header.Channels[c];
    w = Samples(channel.XSampling, startX, int64_t(startX) + width - 1);
    h = Samples(channel.YSampling, startY, int64_t(startY) + height - 1);
  };
  auto blocks = [](int64_t w, int64_t h)
  { return static_cast<uint64_t>((w + 7) / 8) * static_cast<uint64_t>((h + 7) / 8); };

  std::vector<bool> grouped(n, false);
  for (const auto& entry : groups)
  {
    const std::array<int, 3>& idx = entry.second;
    if (idx[0] < 0 || idx[1] < 0 || idx[2] < 0)
    {
      continue;
    }
    const vtkOpenEXRChannel& r = header.Channels[static_cast<size_t>(idx[0])];
    bool sameSampling = true;
    for (int k : idx)
    {
      const vtkOpenEXRChannel& other = header.Channels[static_cast<size_t>(k)];
      sameSampling =
        sameSampling && other.XSampling == r.XSampling && other.YSampling == r.YSampling;
    }
    if (!sameSampling)
    {
      continue;
    }
    for (int k : idx)
    {
      if (scheme[static_cast<size_t>(k)] != LossyDCT)
      {
        error = "its rules put channel '" + header.Channels[static_cast<size_t>(k)].Name +
          "' in a colour group but do not make it lossy";
        return false;
      }
      grouped[static_cast<size_t>(k)] = true;
    }
    int64_t w = 0, h = 0;
    size(static_cast<size_t>(idx[0]), w, h);
    need.Blocks += 3 * blocks(w, h);
    ++need.LossyGroups;
  }
  for (size_t c = 0; c < n; ++c)
  {
    int64_t w = 0, h = 0;
    size(c, w, h);
    const uint64_t bytes = static_cast<uint64_t>(w * h * BytesOf(header.Channels[c].Type));
    if (scheme[c] == LossyDCT && header.Channels[c].Type == EXR_PIXEL_UINT)
    {
      // OpenEXR's DCT decoder writes 2 of the 4 bytes of each UINT sample.
      error = "its rules make the UINT channel '" + header.Channels[c].Name + "' lossy";
      return false;
    }
    if (scheme[c] == LossyDCT && !grouped[c])
    {
      need.Blocks += blocks(w, h);
      ++need.LossyGroups;
    }
    else if (scheme[c] == RLE)
    {
      need.RLEBytes += bytes;
    }
    else if (scheme[c] == Unknown)
    {
      need.UnknownBytes += bytes;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// Inflate a zlib stream that must decode to exactly `expected` bytes.
bool InflateExactly(const uint8_t* data, uint64_t size, uint64_t expected,
  std::vector<uint8_t>& out, uint64_t& produced)
{
  out.assign(static_cast<size_t>(expected) + 1, 0); // one spare byte shows a longer stream
  z_stream stream{};
  if (inflateInit(&stream) != Z_OK)
  {
    return false;
  }
  int result = Z_OK;
  uint64_t consumed = 0;
  produced = 0;
  // zlib counts in 32-bit units: feed and drain in pieces.
  while (result == Z_OK)
  {
    const uint64_t inPiece = std::min<uint64_t>(size - consumed, 1u << 30);
    const uint64_t outPiece = std::min<uint64_t>(out.size() - produced, 1u << 30);
    stream.next_in = const_cast<Bytef*>(data + consumed);
    stream.avail_in = static_cast<uInt>(inPiece);
    stream.next_out = out.data() + produced;
    stream.avail_out = static_cast<uInt>(outPiece);
    result = inflate(&stream, Z_NO_FLUSH);
    consumed += inPiece - stream.avail_in;
    produced += outPiece - stream.avail_out;
    if (result == Z_OK && stream.avail_in == inPiece && stream.avail_out == outPiece)
    {
      break; // no progress: the input ended before the stream did
    }
  }
  inflateEnd(&stream);
  out.resize(static_cast<size_t>(std::min(produced, expected)));
  return result == Z_STREAM_END && produced == expected;
}

//------------------------------------------------------------------------------
// The AC values that `blocks` blocks consume, each until its 63 coefficients are filled:
// 0xff00 ends a block, 0xffNN skips NN coefficients, anything else is one coefficient.
uint64_t ConsumedACValues(const std::vector<uint16_t>& values, uint64_t blocks, bool& overrun)
{
  overrun = false;
  size_t at = 0;
  for (uint64_t b = 0; b < blocks; ++b)
  {
    int coefficient = 1;
    while (coefficient < 64)
    {
      if (at >= values.size())
      {
        overrun = true;
        return at;
      }
      const uint16_t value = values[at++];
      if (value == 0xff00)
      {
        coefficient = 64;
      }
      else if ((value >> 8) == 0xff)
      {
        coefficient += value & 0xff;
      }
      else
      {
        ++coefficient;
      }
    }
  }
  return at;
}

std::string Sizes(uint64_t found, uint64_t needed)
{
  return std::to_string(found) + " where the channel list needs " + std::to_string(needed);
}

//------------------------------------------------------------------------------
std::string CheckAC(
  const uint8_t* data, uint64_t size, uint64_t coding, uint64_t count, uint64_t blocks, int groups)
{
  if (count > blocks * 63)
  {
    return "its AC count is " + std::to_string(count) + ", more than its " +
      std::to_string(blocks) + " blocks can hold";
  }
  if (groups <= 1 && (size > 0 || count == 0))
  {
    // One DCT decoder (an RGB group, or one lossy channel: most files): OpenEXR 3.1 decodes
    // exactly `count` values or throws, and bounds that decoder's reads by them, so nothing
    // unset can be read. Only a second decoder reads past its own values unchecked.
    return std::string();
  }
  std::vector<uint16_t> values;
  if (size > 0)
  {
    if (coding == StaticHuffman)
    {
      std::string error;
      if (!vtkOpenEXRHuffmanDecode(data, static_cast<size_t>(size), count, values, error))
      {
        return "its AC stream: " + error;
      }
    }
    else if (coding == Deflate)
    {
      std::vector<uint8_t> bytes;
      uint64_t produced = 0;
      if (!InflateExactly(data, size, count * 2, bytes, produced))
      {
        return "its AC stream inflates to " + std::to_string(produced) + " bytes, not " +
          std::to_string(count * 2);
      }
      values.resize(static_cast<size_t>(count));
      for (size_t i = 0; i < values.size(); ++i)
      {
        values[i] = static_cast<uint16_t>(bytes[2 * i] | (bytes[2 * i + 1] << 8));
      }
    }
    else
    {
      return "its AC compression " + std::to_string(coding) + " is unknown";
    }
  }
  bool overrun = false;
  const uint64_t consumed = ConsumedACValues(values, blocks, overrun);
  if (overrun || consumed != values.size())
  {
    return "its AC stream holds " + std::to_string(values.size()) + " values where its " +
      std::to_string(blocks) + " blocks read " + (overrun ? "more" : std::to_string(consumed));
  }
  return std::string();
}
}

//------------------------------------------------------------------------------
std::string vtkOpenEXRCheckDWAChunk(const vtkOpenEXRHeader& header, const uint8_t* packed,
  uint64_t packedSize, int startX, int startY, int width, int height)
{
  if (packedSize < HeaderBytes)
  {
    return "it is shorter than its header";
  }
  uint64_t word[HeaderWords];
  for (int i = 0; i < HeaderWords; ++i)
  {
    word[i] = vtkOpenEXRLoadLE64(packed + 8 * i);
  }
  if (word[Version] > 2)
  {
    return "its version " + std::to_string(word[Version]) + " is unknown";
  }
  for (int i : { UnknownPackedSize, ACPackedSize, DCPackedSize, RLEPackedSize })
  {
    if (word[i] > packedSize)
    {
      return "a stream claims " + std::to_string(word[i]) + " bytes, past its end";
    }
  }
  std::vector<Rule> rules;
  uint64_t ruleBytes = 0;
  if (word[Version] < 2)
  {
    rules = LegacyRules();
  }
  else
  {
    std::string error;
    if (!ParseRules(packed + HeaderBytes, packedSize - HeaderBytes, rules, ruleBytes, error))
    {
      return error;
    }
  }
  const uint64_t streams =
    word[UnknownPackedSize] + word[ACPackedSize] + word[DCPackedSize] + word[RLEPackedSize];
  if (HeaderBytes + ruleBytes + streams > packedSize)
  {
    return "its streams claim " + std::to_string(streams) + " bytes, past its end";
  }
  Requirements need;
  std::string error;
  if (!Require(header, rules, startX, startY, width, height, need, error))
  {
    return error;
  }

  const uint8_t* unknown = packed + HeaderBytes + ruleBytes;
  const uint8_t* ac = unknown + word[UnknownPackedSize];
  // UNKNOWN: OpenEXR 3.1 inflates it without checking how many bytes came out.
  if (word[UnknownDecodedSize] != need.UnknownBytes)
  {
    return "its UNKNOWN size is " + Sizes(word[UnknownDecodedSize], need.UnknownBytes) + " bytes";
  }
  if (need.UnknownBytes > 0)
  {
    std::vector<uint8_t> bytes;
    uint64_t produced = 0;
    if (!InflateExactly(unknown, word[UnknownPackedSize], need.UnknownBytes, bytes, produced))
    {
      return "its UNKNOWN stream inflates to " + Sizes(produced, need.UnknownBytes) + " bytes";
    }
  }
  if (word[RLERawSize] != need.RLEBytes)
  {
    return "its RLE size is " + Sizes(word[RLERawSize], need.RLEBytes) + " bytes";
  }
  if (word[DCCount] != need.Blocks)
  {
    return "its DC count is " + Sizes(word[DCCount], need.Blocks) + " blocks";
  }
  return CheckAC(
    ac, word[ACPackedSize], word[ACCompression], word[ACCount], need.Blocks, need.LossyGroups);
}

//------------------------------------------------------------------------------
bool vtkOpenEXRCheckDWAChunks(vtkOpenEXRCoreFile& file, const vtkOpenEXRHeader& header,
  const std::vector<vtkOpenEXRChunk>& chunks, vtkOpenEXRFailure& failure)
{
  std::atomic<bool> stop{ false };
  std::mutex lock;
  vtkSMPTools::For(0, static_cast<vtkIdType>(chunks.size()), 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<uint8_t> packed;
      for (vtkIdType i = begin; i < end && !stop.load(); ++i)
      {
        const vtkOpenEXRChunk& chunk = chunks[static_cast<size_t>(i)];
        const exr_chunk_info_t& info = chunk.Info;
        if (info.packed_size >= info.unpacked_size)
        {
          continue; // stored as is: every byte comes from the file
        }
        packed.resize(static_cast<size_t>(info.packed_size));
        std::string problem;
        const exr_result_t read = exr_read_chunk(file.Context, header.Part, &info, packed.data());
        if (read != EXR_ERR_SUCCESS)
        {
          problem = "cannot be read: " + file.Describe(read);
        }
        else
        {
          problem = vtkOpenEXRCheckDWAChunk(header, packed.data(), info.packed_size, chunk.StartX,
            chunk.StartY, info.width, info.height);
        }
        if (!problem.empty() && !stop.exchange(true))
        {
          std::ostringstream message;
          message << chunk.Describe() << ": " << problem;
          std::lock_guard<std::mutex> guard(lock);
          failure.Set(vtkErrorCode::FileFormatError, message.str());
        }
      }
    });
  return !stop.load();
}

// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// VTK-HeaderTest-Exclude: vtkOpenEXRHuffman.cxx
#include "vtkOpenEXRHuffman.h"
#include "vtkOpenEXRBytes.h"

#include <array>

namespace
{
constexpr int LongestCode = 58;         // code lengths are 6-bit values below the run codes
constexpr uint64_t ShortZeroRun = 59;   // 59..62: 2..5 unused symbols
constexpr uint64_t LongZeroRun = 63;    // 63, then 8 bits: 6..261 unused symbols
constexpr uint32_t SymbolLimit = 65537; // 65536 values and the run code
constexpr int TableBits = 12;           // codes up to this long are found with one look-up

//------------------------------------------------------------------------------
// Bits, most significant first, that never reads past `limit` bits: a 64-bit window refilled
// a byte at a time.
class BitReader
{
public:
  BitReader(const uint8_t* data, uint64_t limit)
    : Data(data)
    , Limit(limit)
    , Bytes((limit + 7) / 8)
  {
  }
  // The next `bits` (at most 56) without consuming them, when that many remain.
  bool Peek(int bits, uint64_t& value)
  {
    while (this->Count <= 56 && this->Next < this->Bytes)
    {
      this->Window = (this->Window << 8) | this->Data[this->Next++];
      this->Count += 8;
    }
    if (this->Limit - this->Position < static_cast<uint64_t>(bits))
    {
      return false;
    }
    value = (this->Window >> (this->Count - bits)) & ((uint64_t(1) << bits) - 1);
    return true;
  }
  void Skip(int bits)
  {
    this->Count -= bits;
    this->Position += static_cast<uint64_t>(bits);
  }
  bool Read(int bits, uint64_t& value)
  {
    if (!this->Peek(bits, value))
    {
      return false;
    }
    this->Skip(bits);
    return true;
  }
  uint64_t Position = 0;

private:
  const uint8_t* Data;
  uint64_t Limit;
  uint64_t Bytes;
  uint64_t Next = 0;
  uint64_t Window = 0;
  int Count = 0; // bits in Window not yet consumed
};

//------------------------------------------------------------------------------
// The canonical code built from the symbols' lengths.
class CanonicalCode
{
public:
  bool Build(const std::vector<uint8_t>& lengths, uint32_t first, std::string& error);
  // Decode one symbol; false when the bits are not a code.
  bool Next(BitReader& bits, uint32_t& symbol) const;

private:
  std::array<uint64_t, LongestCode + 1> Count{};
  std::array<uint64_t, LongestCode + 1> FirstCode{};
  std::array<uint64_t, LongestCode + 1> FirstIndex{};
  std::vector<uint32_t> Symbols; // by length, then by symbol
  // For each TableBits-bit prefix: (length << 24 | index into Symbols), or 0 for longer codes.
  std::vector<uint32_t> Table;
};

bool CanonicalCode::Build(const std::vector<uint8_t>& lengths, uint32_t first, std::string& error)
{
  for (uint8_t length : lengths)
  {
    ++this->Count[length];
  }
  // Kraft's sum in units of 2^-58: exactly 2^58 for a complete code.
  const uint64_t whole = uint64_t(1) << LongestCode;
  uint64_t sum = 0;
  for (int length = 1; length <= LongestCode; ++length)
  {
    const uint64_t unit = uint64_t(1) << (LongestCode - length);
    if (this->Count[length] > (whole - sum) / unit)
    {
      error = "the Huffman table is not a prefix code";
      return false;
    }
    sum += this->Count[length] * unit;
  }
  if (sum != whole)
  {
    error = "the Huffman table is not a complete prefix code";
    return false;
  }
  // Longer codes take the lower values: walk from the longest length to the shortest.
  uint64_t code = 0;
  for (int length = LongestCode; length > 0; --length)
  {
    this->FirstCode[length] = code;
    code = (code + this->Count[length]) >> 1;
  }
  uint64_t index = 0;
  for (int length = 1; length <= LongestCode; ++length)
  {
    this->FirstIndex[length] = index;
    index += this->Count[length];
  }
  this->Symbols.assign(index, 0);
  std::array<uint64_t, LongestCode + 1> next = this->FirstIndex;
  for (size_t i = 0; i < lengths.size(); ++i)
  {
    if (lengths[i] > 0)
    {
      this->Symbols[next[lengths[i]]++] = first + static_cast<uint32_t>(i);
    }
  }
  this->Table.assign(size_t(1) << TableBits, 0);
  for (int length = 1; length <= TableBits; ++length)
  {
    for (uint64_t k = 0; k < this->Count[length]; ++k)
    {
      const uint64_t prefix = (this->FirstCode[length] + k) << (TableBits - length);
      const uint64_t span = uint64_t(1) << (TableBits - length);
      for (uint64_t p = prefix; p < prefix + span; ++p)
      {
        this->Table[p] = (static_cast<uint32_t>(length) << 24) |
          static_cast<uint32_t>(this->FirstIndex[length] + k);
      }
    }
  }
  return true;
}

bool CanonicalCode::Next(BitReader& bits, uint32_t& symbol) const
{
  uint64_t prefix = 0;
  if (bits.Peek(TableBits, prefix) && this->Table[prefix] != 0)
  {
    const uint32_t entry = this->Table[prefix];
    bits.Skip(static_cast<int>(entry >> 24));
    symbol = this->Symbols[entry & 0xffffffu];
    return true;
  }
  uint64_t code = 0;
  for (int length = 1; length <= LongestCode; ++length)
  {
    uint64_t bit = 0;
    if (!bits.Read(1, bit))
    {
      return false;
    }
    code = (code << 1) | bit;
    if (code >= this->FirstCode[length] && code - this->FirstCode[length] < this->Count[length])
    {
      symbol = this->Symbols[this->FirstIndex[length] + (code - this->FirstCode[length])];
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
// The packed code lengths of symbols first..last; `bytes` is set to the bytes they used.
bool UnpackLengths(const uint8_t* data, size_t size, uint32_t first, uint32_t last,
  std::vector<uint8_t>& lengths, size_t& bytes, std::string& error)
{
  BitReader bits(data, static_cast<uint64_t>(size) * 8);
  lengths.assign(static_cast<size_t>(last - first) + 1, 0);
  for (size_t i = 0; i < lengths.size(); ++i)
  {
    uint64_t length = 0;
    if (!bits.Read(6, length))
    {
      error = "the Huffman table is truncated";
      return false;
    }
    uint64_t zeros = 0;
    if (length == LongZeroRun)
    {
      uint64_t run = 0;
      if (!bits.Read(8, run))
      {
        error = "the Huffman table is truncated";
        return false;
      }
      zeros = run + 6;
    }
    else if (length >= ShortZeroRun)
    {
      zeros = length - ShortZeroRun + 2;
    }
    else
    {
      lengths[i] = static_cast<uint8_t>(length);
      continue;
    }
    if (zeros > lengths.size() - i)
    {
      error = "the Huffman table runs past its last symbol";
      return false;
    }
    i += static_cast<size_t>(zeros) - 1; // already zero
  }
  bytes = static_cast<size_t>((bits.Position + 7) / 8);
  return true;
}
}

//------------------------------------------------------------------------------
bool vtkOpenEXRHuffmanDecode(const uint8_t* data, size_t size, uint64_t count,
  std::vector<uint16_t>& values, std::string& error)
{
  values.clear();
  if (size < 20)
  {
    // OpenEXR reads a stream shorter than its header as no values at all.
    if (count != 0)
    {
      error = "the Huffman stream is shorter than its header";
      return false;
    }
    return true;
  }
  const uint32_t first = vtkOpenEXRLoadLE32(data);
  const uint32_t last = vtkOpenEXRLoadLE32(data + 4);
  const uint32_t codedBits = vtkOpenEXRLoadLE32(data + 12);
  if (first >= SymbolLimit || last >= SymbolLimit || first > last || codedBits > 0x7fffffffu)
  {
    error = "the Huffman header is invalid (symbols " + std::to_string(first) + " to " +
      std::to_string(last) + ", " + std::to_string(codedBits) + " bits)";
    return false;
  }
  std::vector<uint8_t> lengths;
  size_t tableBytes = 0;
  if (!UnpackLengths(data + 20, size - 20, first, last, lengths, tableBytes, error))
  {
    return false;
  }
  const uint8_t* coded = data + 20 + tableBytes;
  const size_t codedSize = size - 20 - tableBytes;
  if ((static_cast<uint64_t>(codedBits) + 7) / 8 > codedSize)
  {
    error = "the Huffman stream claims more bits than it holds";
    return false;
  }
  CanonicalCode code;
  if (!code.Build(lengths, first, error))
  {
    return false;
  }
  // The run code repeats the previous value; every other symbol is a value.
  const uint32_t runCode = last;
  values.reserve(static_cast<size_t>(count));
  BitReader bits(coded, codedBits);
  while (bits.Position < codedBits)
  {
    uint32_t symbol = 0;
    if (!code.Next(bits, symbol))
    {
      error = "the Huffman stream ends inside a code";
      return false;
    }
    if (symbol == runCode)
    {
      uint64_t run = 0;
      if (!bits.Read(8, run))
      {
        error = "the Huffman stream ends inside a run";
        return false;
      }
      if (values.empty() || run > count - values.size())
      {
        error = values.empty() ? "the Huffman stream starts with a run"
                               : "the Huffman stream decodes to more values than expected";
        return false;
      }
      const uint16_t previous = values.back();
      values.insert(values.end(), static_cast<size_t>(run), previous);
    }
    else
    {
      if (values.size() >= count)
      {
        error = "the Huffman stream decodes to more values than expected";
        return false;
      }
      values.push_back(static_cast<uint16_t>(symbol));
    }
  }
  if (values.size() != count)
  {
    error = "the Huffman stream decodes to " + std::to_string(values.size()) + " values, not " +
      std::to_string(count);
    return false;
  }
  return true;
}

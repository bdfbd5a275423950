// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkOpenEXRHuffman.h
 * @brief  (private to vtkOpenEXRReader) an independent, checked decoder for OpenEXR's static
 *         Huffman streams (the AC coefficients of DWAA/DWAB chunks).
 *
 * The stream is a 20-byte header (smallest and largest symbol, table length, number of coded
 * bits, a reserved word; little-endian), the code lengths of the symbols in between packed as
 * 6-bit values with two run codes for unused symbols, then the coded bits, most significant
 * first. Codes are canonical: from the lengths alone, longer codes take the numerically lower
 * values, and codes of one length increase with the symbol. The largest symbol is a run code:
 * it is followed by 8 bits that repeat the previous value that many times.
 *
 * The decoder accepts a stream only if it is a complete prefix code (Kraft's sum exactly 1,
 * as every Huffman table that OpenEXR writes is), all of its bits decode, and they decode to
 * exactly the expected number of values. A complete prefix code decodes one way only, so an
 * accepted stream gives the values that OpenEXR's own decoders give.
 */
#ifndef vtkOpenEXRHuffman_h
#define vtkOpenEXRHuffman_h

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

/**
 * Decode `size` bytes at `data` into exactly `count` values. On failure, returns false with
 * `error` saying what is wrong in one phrase.
 */
bool vtkOpenEXRHuffmanDecode(const uint8_t* data, size_t size, uint64_t count,
  std::vector<uint16_t>& values, std::string& error);

#endif
// VTK-HeaderTest-Exclude: vtkOpenEXRHuffman.h

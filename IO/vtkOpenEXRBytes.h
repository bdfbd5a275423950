// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkOpenEXRBytes.h
 * @brief  (private to vtkOpenEXRReader) little-endian loads, the EXR byte order, that work on
 *         any host and any alignment: for the decoder, the DWA check and its Huffman decoder.
 */
#ifndef vtkOpenEXRBytes_h
#define vtkOpenEXRBytes_h

#include <cstdint>

inline uint16_t vtkOpenEXRLoadLE16(const uint8_t* p)
{
  return static_cast<uint16_t>(p[0] | (p[1] << 8));
}

inline uint32_t vtkOpenEXRLoadLE32(const uint8_t* p)
{
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) |
    (static_cast<uint32_t>(p[2]) << 16) | (static_cast<uint32_t>(p[3]) << 24);
}

inline uint64_t vtkOpenEXRLoadLE64(const uint8_t* p)
{
  return static_cast<uint64_t>(vtkOpenEXRLoadLE32(p)) |
    (static_cast<uint64_t>(vtkOpenEXRLoadLE32(p + 4)) << 32);
}

#endif
// VTK-HeaderTest-Exclude: vtkOpenEXRBytes.h

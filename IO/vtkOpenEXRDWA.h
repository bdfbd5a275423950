// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkOpenEXRDWA.h
 * @brief  (private to vtkOpenEXRReader) every DWAA/DWAB chunk checked against the channel list
 *         before OpenEXR's C++ library decodes it.
 *
 * A DWA chunk holds four streams: UNKNOWN (deflate of planar bytes), AC (static Huffman or
 * deflate of run-length coded DCT coefficients), DC (deflate of one value a block) and RLE
 * (deflate of run-length coded bytes). Its header gives each stream's compressed and decoded
 * sizes, and (from version 2) the rules that class each channel as lossy DCT, RLE or UNKNOWN.
 *
 * OpenEXR 3.1 trusts those sizes: a stream that decodes to fewer bytes than the channels need
 * leaves its buffers partly unset, and the unset bytes are copied into the image. So before
 * the library sees a chunk, every stream is checked against what the channel list requires:
 * - UNKNOWN: decoded here, to exactly the bytes of the UNKNOWN channels;
 * - RLE: the raw size is exactly the bytes of the RLE channels (the library checks that the
 *   stream decodes to its raw size);
 * - DC: exactly one value per 8x8 block of every lossy channel (the library checks that the
 *   stream holds its count);
 * - AC: where there are two DCT decoders or more (colour groups and lone lossy channels),
 *   decoded here (vtkOpenEXRHuffman.h or deflate) to exactly the count the header gives, and
 *   that count is exactly what the blocks of all lossy channels consume: OpenEXR 3.1 bounds
 *   only the first decoder's reads by it. With one decoder, its own bound suffices.
 * A chunk stored uncompressed (no smaller than its decoded size) is all file bytes and is not
 * checked further.
 */
#ifndef vtkOpenEXRDWA_h
#define vtkOpenEXRDWA_h

#include "vtkOpenEXRHeader.h"

#include <vector>

/**
 * Check every chunk of `chunks` (a DWAA or DWAB part, validated by vtkOpenEXRReadChunkTable),
 * on several threads. On the first chunk that fails, returns false with a message that names
 * the chunk and the sizes that disagree.
 */
bool vtkOpenEXRCheckDWAChunks(vtkOpenEXRCoreFile& file, const vtkOpenEXRHeader& header,
  const std::vector<vtkOpenEXRChunk>& chunks, vtkOpenEXRFailure& failure);

/**
 * Check one chunk's packed bytes; `startX`, `startY`, `width` and `height` are its pixels.
 * Returns an empty string when it is sound, else what is wrong.
 */
std::string vtkOpenEXRCheckDWAChunk(const vtkOpenEXRHeader& header, const uint8_t* packed,
  uint64_t packedSize, int startX, int startY, int width, int height);

#endif
// VTK-HeaderTest-Exclude: vtkOpenEXRDWA.h

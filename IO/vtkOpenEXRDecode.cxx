// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenEXRDecode.h"
#include "vtkOpenEXRBytes.h"
#include "vtkOpenEXRThreadPool.h"

#include "vtkAlgorithm.h"
#include "vtkErrorCode.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputPart.h>
#include <ImfMultiPartInputFile.h>
#include <ImfRgba.h>
#include <ImfRgbaFile.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <new>
#include <thread>

namespace
{
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
// One thread's decoder: the core library's pipeline (whose buffers it reuses from chunk to
// chunk) and the output component of each channel. The library only reads and decompresses;
// the unpacking into the interleaved output is ours: the core library's fast interleaving
// paths of this release assume the output components are in file (alphabetical) order, which
// R, G, B, A is not.
class vtkOpenEXRChunkDecoder
{
public:
  explicit vtkOpenEXRChunkDecoder(exr_const_context_t context)
    : Context(context)
  {
  }
  ~vtkOpenEXRChunkDecoder()
  {
    if (this->Initialized)
    {
      exr_decoding_destroy(this->Context, &this->Pipeline);
    }
  }
  vtkOpenEXRChunkDecoder(const vtkOpenEXRChunkDecoder&) = delete;
  vtkOpenEXRChunkDecoder& operator=(const vtkOpenEXRChunkDecoder&) = delete;

  bool Decode(vtkOpenEXRCoreFile& file, const vtkOpenEXRHeader& header,
    const vtkOpenEXRChunk& chunk, void* output, bool unsignedOutput, vtkOpenEXRFailure& failure);

private:
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

  exr_const_context_t Context;
  exr_decode_pipeline_t Pipeline{}; // zeroed, as EXR_DECODE_PIPELINE_INITIALIZER
  bool Initialized = false;
  std::vector<int> ComponentOf;
};

//------------------------------------------------------------------------------
bool vtkOpenEXRChunkDecoder::Decode(vtkOpenEXRCoreFile& file, const vtkOpenEXRHeader& header,
  const vtkOpenEXRChunk& chunkEntry, void* output, bool unsignedOutput, vtkOpenEXRFailure& failure)
{
  const exr_chunk_info_t& chunk = chunkEntry.Info;
  const int32_t startX = chunkEntry.StartX, startY = chunkEntry.StartY;
  exr_result_t result = this->Start(header.Part, chunk);
  exr_decode_pipeline_t& pipeline = this->Pipeline;
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
    return failure.Set(vtkErrorCode::FileFormatError,
      chunkEntry.Describe() + ": cannot be decoded: " + file.Describe(result));
  }

  // The decompressed chunk holds, line by line, each channel that has samples on that line
  // (y divisible by its y sampling), in channel-list order. Check that the layout the
  // library describes accounts for exactly the bytes it produced before walking it.
  std::vector<int>& componentOf = this->ComponentOf;
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
      (channel.data_type == EXR_PIXEL_HALF) != (channel.bytes_per_element == 2) ||
      (channel.x_samples == 1 && channel.width != chunk.width))
    {
      return failure.Set(vtkErrorCode::FileFormatError,
        chunkEntry.Describe() + ": does not match the channel layout");
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
    return failure.Set(vtkErrorCode::FileFormatError,
      chunkEntry.Describe() + ": its channels need " + std::to_string(expectedBytes) + " bytes");
  }
  if (!output)
  {
    return true;
  }

  const size_t components = static_cast<size_t>(header.NumberOfComponents);
  const size_t width = static_cast<size_t>(header.Width);
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
        // Selected channels are full resolution (vtkOpenEXRReadHeader), so count is the
        // chunk's width.
        const size_t first =
          (row * width + column) * components + static_cast<size_t>(componentOf[c]);
        if (unsignedOutput)
        {
          uint32_t* out = static_cast<uint32_t*>(output) + first;
          for (size_t x = 0; x < count; ++x, out += components)
          {
            *out = vtkOpenEXRLoadLE32(in + x * 4);
          }
        }
        else if (channel.data_type == EXR_PIXEL_HALF)
        {
          float* out = static_cast<float*>(output) + first;
          for (size_t x = 0; x < count; ++x, out += components)
          {
            *out = HalfBitsToFloat(vtkOpenEXRLoadLE16(in + x * 2));
          }
        }
        else if (channel.data_type == EXR_PIXEL_FLOAT)
        {
          float* out = static_cast<float*>(output) + first;
          for (size_t x = 0; x < count; ++x, out += components)
          {
            const uint32_t bits = vtkOpenEXRLoadLE32(in + x * 4);
            std::memcpy(out, &bits, sizeof(bits));
          }
        }
        else
        {
          // UINT among float channels: the nearest float (exact below 2^24).
          float* out = static_cast<float*>(output) + first;
          for (size_t x = 0; x < count; ++x, out += components)
          {
            *out = static_cast<float>(vtkOpenEXRLoadLE32(in + x * 4));
          }
        }
      }
      in += count * static_cast<size_t>(bytes);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// The vtkSMPTools functor: each thread decodes its ranges of chunks with its own decoder. The
// first failure wins and stops the others; progress and abort are handled on the thread that
// called Execute(), the only one allowed to fire VTK events.
class vtkOpenEXRDecodeFunctor
{
public:
  vtkOpenEXRDecodeFunctor(vtkOpenEXRCoreFile& file, const vtkOpenEXRHeader& header,
    const std::vector<vtkOpenEXRChunk>& chunks, void* output, bool unsignedOutput,
    vtkAlgorithm* progress)
    : File(file)
    , Header(header)
    , Chunks(chunks)
    , Output(output)
    , UnsignedOutput(unsignedOutput)
    , Progress(progress)
    , Caller(std::this_thread::get_id())
  {
  }

  void operator()(vtkIdType begin, vtkIdType end)
  {
    std::shared_ptr<vtkOpenEXRChunkDecoder>& decoder = this->Decoders.Local();
    if (!decoder)
    {
      decoder = std::make_shared<vtkOpenEXRChunkDecoder>(this->File.Context);
    }
    const bool caller = std::this_thread::get_id() == this->Caller;
    for (vtkIdType i = begin; i < end && !this->Stop.load(); ++i)
    {
      vtkOpenEXRFailure failure;
      if (!decoder->Decode(this->File, this->Header, this->Chunks[static_cast<size_t>(i)],
            this->Output, this->UnsignedOutput, failure))
      {
        this->Fail(failure);
        return;
      }
      const vtkIdType done = ++this->Done;
      if (caller && this->Progress)
      {
        const double fraction = static_cast<double>(done) / this->Chunks.size();
        this->Progress->UpdateProgress(fraction * (this->Output ? 1.0 : 0.5));
        if (this->Progress->GetAbortExecute())
        {
          vtkOpenEXRFailure aborted;
          aborted.Set(vtkErrorCode::UnknownError, "reading was aborted");
          this->Fail(aborted);
          return;
        }
      }
    }
  }

  void Fail(const vtkOpenEXRFailure& failure)
  {
    std::lock_guard<std::mutex> guard(this->Lock);
    if (!this->Stop.exchange(true))
    {
      this->Failure = failure;
    }
  }

  vtkOpenEXRFailure Failure;
  std::atomic<bool> Stop{ false };

private:
  vtkOpenEXRCoreFile& File;
  const vtkOpenEXRHeader& Header;
  const std::vector<vtkOpenEXRChunk>& Chunks;
  void* Output;
  bool UnsignedOutput;
  vtkAlgorithm* Progress;
  std::thread::id Caller;
  vtkSMPThreadLocal<std::shared_ptr<vtkOpenEXRChunkDecoder>> Decoders;
  std::atomic<vtkIdType> Done{ 0 };
  std::mutex Lock;
};

//------------------------------------------------------------------------------
// Run a read through OpenEXR's C++ library, which reports failures as exceptions.
template <typename Read>
bool CatchOpenEXR(vtkOpenEXRFailure& failure, Read&& read)
{
  try
  {
    return read();
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
bool vtkOpenEXRDecodeChunks(vtkOpenEXRCoreFile& file, const vtkOpenEXRHeader& header,
  const std::vector<vtkOpenEXRChunk>& chunks, void* output, bool unsignedOutput,
  vtkAlgorithm* progress, vtkOpenEXRFailure& failure)
{
  vtkOpenEXRDecodeFunctor functor(file, header, chunks, output, unsignedOutput, progress);
  // One chunk per task: a chunk is 1 to 256 scanlines or a tile, large enough to amortize
  // the scheduling, and a failing file stops after the chunks already started.
  vtkSMPTools::For(0, static_cast<vtkIdType>(chunks.size()), 1, functor);
  if (functor.Stop.load())
  {
    failure = functor.Failure;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// Runs only on files whose header and chunks the core library has already validated.
bool vtkOpenEXRConvertLuminanceChroma(const std::string& fileName, const vtkOpenEXRHeader& header,
  float* output, vtkOpenEXRFailure& failure)
{
  return CatchOpenEXR(failure,
    [&]
    {
      Imf::RgbaInputFile input(fileName.c_str(), header.Layer);
      const Imath::Box2i window = input.dataWindow();
      if (window.min.x != header.DataWindow[0] || window.max.x != header.DataWindow[1] ||
        window.min.y != header.DataWindow[2] || window.max.y != header.DataWindow[3])
      {
        return failure.Set(vtkErrorCode::FileFormatError, "inconsistent data window");
      }
      // Strips of rows through a small half-float buffer, never a full-size copy: the C++
      // library keeps the lines its chroma filter needs between consecutive reads.
      const size_t width = static_cast<size_t>(header.Width);
      const int components = header.NumberOfComponents;
      const int stripRows = 64;
      std::vector<Imf::Rgba> strip(width * stripRows);
      for (int y0 = header.DataWindow[2]; y0 <= header.DataWindow[3]; y0 += stripRows)
      {
        const int y1 = std::min(y0 + stripRows - 1, header.DataWindow[3]);
        // The frame buffer is addressed by absolute pixel coordinates; compute its origin with
        // integer arithmetic because the pointer itself lies outside the strip.
        const vtkTypeInt64 origin =
          static_cast<vtkTypeInt64>(y0) * header.Width + header.DataWindow[0];
        const uintptr_t base = reinterpret_cast<uintptr_t>(strip.data()) -
          static_cast<uintptr_t>(origin) * sizeof(Imf::Rgba);
        input.setFrameBuffer(reinterpret_cast<Imf::Rgba*>(base), 1, width);
        input.readPixels(y0, y1);
        const size_t first = static_cast<size_t>(y0 - header.DataWindow[2]) * width;
        const size_t count = static_cast<size_t>(y1 - y0 + 1) * width;
        for (size_t p = 0; p < count; ++p)
        {
          float* out = output + (first + p) * static_cast<size_t>(components);
          out[0] = strip[p].r;
          out[1] = strip[p].g;
          out[2] = strip[p].b;
          if (components == 4)
          {
            out[3] = strip[p].a;
          }
        }
      }
      return true;
    });
}

//------------------------------------------------------------------------------
bool vtkOpenEXRDecodeWithImf(const std::string& fileName, const vtkOpenEXRHeader& header,
  void* output, bool unsignedOutput, vtkOpenEXRFailure& failure)
{
  return CatchOpenEXR(failure,
    [&]
    {
      Imf::MultiPartInputFile file(fileName.c_str(), vtkOpenEXRUseThreadPool(0));
      Imf::InputPart part(file, header.Part);
      const Imath::Box2i window = part.header().dataWindow();
      if (window.min.x != header.DataWindow[0] || window.max.x != header.DataWindow[1] ||
        window.min.y != header.DataWindow[2] || window.max.y != header.DataWindow[3])
      {
        return failure.Set(vtkErrorCode::FileFormatError, "inconsistent data window");
      }
      const size_t components = static_cast<size_t>(header.NumberOfComponents);
      const size_t xStride = 4 * components;
      const size_t yStride = xStride * static_cast<size_t>(header.Width);
      const Imf::PixelType type = unsignedOutput ? Imf::UINT : Imf::FLOAT;
      Imf::FrameBuffer frameBuffer;
      for (size_t k = 0; k < components; ++k)
      {
        // Slice::Make maps absolute pixel coordinates onto the output without forming an
        // out-of-range pointer ourselves.
        frameBuffer.insert(header.Channels[header.Decoded[k]].Name,
          Imf::Slice::Make(type, static_cast<char*>(output) + 4 * k, window, xStride, yStride));
      }
      part.setFrameBuffer(frameBuffer);
      part.readPixels(window.min.y, window.max.y);
      return true;
    });
}

// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenEXRWriter.h"

#include "vtkArrayDispatch.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkOpenEXRThreadPool.h"
#include "vtkPointData.h"
#include "vtkUnsignedIntArray.h"

#include <IexErrnoExc.h>
#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfTileDescription.h>
#include <ImfTiledOutputFile.h>

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <type_traits>
#include <vector>

#ifdef _WIN32
#include <fcntl.h>
#include <io.h>
#include <sys/stat.h>
#else
#include <fcntl.h>
#include <unistd.h>
#endif

vtkStandardNewMacro(vtkOpenEXRWriter);

namespace
{
namespace fs = std::filesystem;

//------------------------------------------------------------------------------
// Create a new, empty file with a name nobody else holds, next to `target` so that the final
// rename stays within one file system. O_EXCL makes the creation fail rather than follow a
// planted symlink or reuse an existing file.
bool CreateTemporaryFile(const fs::path& target, fs::path& temporary, std::string& error)
{
  fs::path directory = target.parent_path();
  if (directory.empty())
  {
    directory = ".";
  }
  std::random_device device;
  std::mt19937_64 generator((static_cast<uint64_t>(device()) << 32) ^ device());
  for (int attempt = 0; attempt < 16; ++attempt)
  {
    std::ostringstream name;
    name << "." << target.filename().string() << "." << std::hex << generator() << ".tmp";
    temporary = directory / name.str();
#ifdef _WIN32
    const int fd =
      _wopen(temporary.c_str(), _O_WRONLY | _O_CREAT | _O_EXCL | _O_BINARY, _S_IREAD | _S_IWRITE);
    if (fd >= 0)
    {
      _close(fd);
      return true;
    }
#else
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0)
    {
      ::close(fd);
      return true;
    }
#endif
    if (errno != EEXIST)
    {
      error = std::strerror(errno);
      return false;
    }
  }
  error = "no unused temporary file name";
  return false;
}

//------------------------------------------------------------------------------
// Copy the scalars, interleaved, into `out` as T (float, half or uint32). Double goes through
// float first, as documented, so that half output rounds the same way for float and double.
template <typename T>
struct vtkOpenEXRConvertWorker
{
  std::vector<T>* Out;

  template <typename ArrayT>
  void operator()(ArrayT* array)
  {
    using ValueT = vtk::GetAPIType<ArrayT>;
    const auto values = vtk::DataArrayValueRange(array);
    T* out = this->Out->data();
    for (const ValueT value : values)
    {
      *out++ = Convert(value);
    }
  }

  template <typename ValueT>
  static T Convert(ValueT value)
  {
    if constexpr (std::is_same<T, uint32_t>::value)
    {
      // Only reached for unsigned int scalars (UINT channels).
      return static_cast<T>(value);
    }
    else if constexpr (std::is_same<T, Imath::half>::value)
    {
      // Finite values beyond the half range clamp to +/-65504 (HALF_MAX) instead of rounding
      // to +/-Inf, so that finite input never becomes Inf; infinities and NaN are kept.
      const float f = ToFloat(value);
      if (std::isfinite(f) && std::fabs(f) > 65504.0f)
      {
        return static_cast<T>(f > 0 ? 65504.0f : -65504.0f);
      }
      return static_cast<T>(f);
    }
    else
    {
      return static_cast<T>(ToFloat(value));
    }
  }

  static float ToFloat(float value) { return value; }
  static float ToFloat(unsigned int value) { return static_cast<float>(value); }
  static float ToFloat(double value)
  {
    // IEEE round-to-nearest, spelled out because a double beyond the float range makes a
    // plain cast undefined in C++: at or above FLT_MAX + half an ulp (2^103) it rounds to Inf.
    const double overflow = static_cast<double>(FLT_MAX) + std::ldexp(1.0, 103);
    if (std::fabs(value) >= overflow)
    {
      const float infinity = std::numeric_limits<float>::infinity();
      return value > 0 ? infinity : -infinity;
    }
    if (std::fabs(value) > static_cast<double>(FLT_MAX))
    {
      return value > 0 ? FLT_MAX : -FLT_MAX;
    }
    return static_cast<float>(value);
  }
};

//------------------------------------------------------------------------------
template <typename T>
void ConvertScalars(vtkDataArray* scalars, std::vector<T>& out)
{
  out.resize(static_cast<size_t>(scalars->GetNumberOfValues()));
  vtkOpenEXRConvertWorker<T> worker{ &out };
  using Types = vtkTypeList::Create<float, double, unsigned int>;
  if (!vtkArrayDispatch::DispatchByValueType<Types>::Execute(scalars, worker))
  {
    // Other array implementations of the same value types: go through the generic API.
    worker(scalars);
  }
}

//------------------------------------------------------------------------------
// Why an image of this extent cannot be written, or "" when it can: OpenEXR images are
// non-empty and two-dimensional.
std::string CheckExtent(const int extent[6])
{
  if (extent[0] > extent[1] || extent[2] > extent[3] || extent[4] > extent[5])
  {
    return "the input image is empty";
  }
  if (extent[4] != extent[5])
  {
    std::ostringstream message;
    message << "the input has " << (extent[5] - extent[4] + 1)
            << " z slices; an OpenEXR image holds one (extract it with vtkExtractVOI)";
    return message.str();
  }
  return std::string();
}

//------------------------------------------------------------------------------
// Why `scalars` cannot be written as a width x height image, or "" when they can.
std::string CheckScalars(vtkDataArray* scalars, vtkIdType width, vtkIdType height)
{
  if (width > VTK_INT_MAX || height > VTK_INT_MAX)
  {
    return "the input extent is too large for OpenEXR";
  }
  const vtkIdType pixels = width * height;
  if (!scalars || scalars->GetNumberOfTuples() != pixels)
  {
    return "the input has no point scalars matching its extent";
  }
  const int components = scalars->GetNumberOfComponents();
  if (components < 1 || components > 4)
  {
    std::ostringstream message;
    message << "the input has " << components << " components; 1 (Y), 2 (YA), 3 (RGB) or 4 "
            << "(RGBA) are supported";
    return message.str();
  }
  const int scalarType = scalars->GetDataType();
  if (scalarType != VTK_FLOAT && scalarType != VTK_DOUBLE && scalarType != VTK_UNSIGNED_INT)
  {
    return std::string("unsupported scalar type ") + scalars->GetDataTypeAsString() +
      "; use float, double or unsigned int";
  }
  return std::string();
}

//------------------------------------------------------------------------------
// The display window: the one set (xmin, xmax, ymin, ymax), else the data window when none
// is (an empty one).
Imath::Box2i DisplayWindowOf(const int window[4], const Imath::Box2i& dataWindow)
{
  if (window[0] <= window[1] && window[2] <= window[3])
  {
    return Imath::Box2i(Imath::V2i(window[0], window[2]), Imath::V2i(window[1], window[3]));
  }
  return dataWindow;
}

//------------------------------------------------------------------------------
// The buffers that hold the pixels when they must be converted for OpenEXR, one per type.
struct PixelBuffers
{
  std::vector<float> Floats;
  std::vector<Imath::half> Halves;
  std::vector<uint32_t> Uints;
};

// The interleaved pixels in the file's pixel type: the scalars' own memory where the bits
// are already right, else a converted copy in `buffers`.
const char* PixelData(vtkDataArray* scalars, Imf::PixelType pixelType, PixelBuffers& buffers)
{
  if (pixelType == Imf::UINT && vtkUnsignedIntArray::FastDownCast(scalars))
  {
    return reinterpret_cast<const char*>(vtkUnsignedIntArray::FastDownCast(scalars)->GetPointer(0));
  }
  if (pixelType == Imf::UINT)
  {
    ConvertScalars(scalars, buffers.Uints);
    return reinterpret_cast<const char*>(buffers.Uints.data());
  }
  if (pixelType == Imf::HALF)
  {
    ConvertScalars(scalars, buffers.Halves);
    return reinterpret_cast<const char*>(buffers.Halves.data());
  }
  if (vtkFloatArray* direct = vtkFloatArray::FastDownCast(scalars))
  {
    // Float to FLOAT is a copy of the bits: OpenEXR reads the array itself.
    return reinterpret_cast<const char*>(direct->GetPointer(0));
  }
  ConvertScalars(scalars, buffers.Floats);
  return reinterpret_cast<const char*>(buffers.Floats.data());
}

//------------------------------------------------------------------------------
// One channel per component (Y, YA, RGB or RGBA) in the header, and the slice of the
// interleaved pixels at `base` that feeds it in the frame buffer.
void AddChannels(Imf::Header& header, Imf::FrameBuffer& frameBuffer, Imf::PixelType pixelType,
  const char* base, int components, const Imath::Box2i& dataWindow, vtkIdType width)
{
  static const char* const channelNames[4][4] = { { "Y" }, { "Y", "A" }, { "R", "G", "B" },
    { "R", "G", "B", "A" } };
  const size_t elementSize = pixelType == Imf::HALF ? sizeof(Imath::half) : 4;
  const size_t xStride = elementSize * static_cast<size_t>(components);
  const size_t yStride = xStride * static_cast<size_t>(width);
  for (int c = 0; c < components; ++c)
  {
    const char* name = channelNames[components - 1][c];
    header.channels().insert(name, Imf::Channel(pixelType));
    // Slice::Make maps absolute pixel coordinates onto our buffer without forming an
    // out-of-range pointer ourselves.
    frameBuffer.insert(
      name, Imf::Slice::Make(pixelType, base + c * elementSize, dataWindow, xStride, yStride));
  }
}

//------------------------------------------------------------------------------
// Write the image to `path`, in tiles or in scan lines. Returns false when the stream failed
// (a full disk), which the output file's destructor does not report; OpenEXR's own errors
// throw.
bool WriteImage(const fs::path& path, const Imf::Header& header,
  const Imf::FrameBuffer& frameBuffer, bool tiled, int height, int numberOfThreads)
{
  std::ofstream stream(path, std::ios::out | std::ios::binary | std::ios::trunc);
  if (!stream)
  {
    throw std::runtime_error("cannot open the temporary file " + path.string());
  }
  {
    Imf::StdOFStream exrStream(stream, path.string().c_str());
    const int threads = vtkOpenEXRUseThreadPool(numberOfThreads);
    if (tiled)
    {
      Imf::TiledOutputFile out(exrStream, header, threads);
      out.setFrameBuffer(frameBuffer);
      out.writeTiles(0, out.numXTiles() - 1, 0, out.numYTiles() - 1);
    }
    else
    {
      Imf::OutputFile out(exrStream, header, threads);
      out.setFrameBuffer(frameBuffer);
      out.writePixels(height);
    }
    // The output file's destructor writes the chunk offset table and swallows any error;
    // the stream state checked below still records it.
  }
  stream.close();
  return !stream.fail();
}

//------------------------------------------------------------------------------
// Move the written temporary file onto the target; throws when that fails. Replacing a file
// keeps its permissions; a new file gets the default (umask) ones.
void ReplaceTarget(const fs::path& temporary, const fs::path& target)
{
  std::error_code ec;
  const fs::file_status previous = fs::status(target, ec);
  if (!ec && fs::is_regular_file(previous))
  {
    fs::permissions(temporary, previous.permissions(), ec);
  }
  fs::rename(temporary, target, ec);
  if (ec)
  {
    throw std::runtime_error("cannot replace the target: " + ec.message());
  }
}
}

//------------------------------------------------------------------------------
vtkOpenEXRWriter::vtkOpenEXRWriter()
  : FileName(nullptr)
  , PixelType(PIXEL_TYPE_FLOAT)
  , Compression(COMPRESSION_ZIP)
  , DisplayWindow{ 0, -1, 0, -1 }
  , Tiled(0)
  , TileSize{ 64, 64 }
  , NumberOfThreads(0)
{
}

//------------------------------------------------------------------------------
vtkOpenEXRWriter::~vtkOpenEXRWriter()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkOpenEXRWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
vtkImageData* vtkOpenEXRWriter::GetImageDataInput()
{
  return vtkImageData::SafeDownCast(this->GetInput());
}

//------------------------------------------------------------------------------
const char* vtkOpenEXRWriter::GetPixelTypeAsString()
{
  return this->PixelType == PIXEL_TYPE_HALF ? "Half" : "Float";
}

//------------------------------------------------------------------------------
const char* vtkOpenEXRWriter::GetCompressionAsString()
{
  static const char* const names[] = { "None", "RLE", "ZIPS", "ZIP", "PIZ", "PXR24", "B44", "B44A",
    "DWAA", "DWAB" };
  return names[this->Compression];
}

//------------------------------------------------------------------------------
int vtkOpenEXRWriter::Write()
{
  // Write() must report this call's outcome, not an earlier one.
  this->SetErrorCode(vtkErrorCode::NoError);
  const int result = this->Superclass::Write();
  return result && this->GetErrorCode() == vtkErrorCode::NoError ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkOpenEXRWriter::WriteData()
{
  this->SetErrorCode(vtkErrorCode::NoError);
  const std::string fileName = this->FileName ? this->FileName : "";
  auto fail = [this, &fileName](unsigned long code, const std::string& message)
  {
    this->SetErrorCode(code);
    vtkErrorMacro("Cannot write OpenEXR file '" << fileName << "': " << message);
  };
  if (fileName.empty())
  {
    fail(vtkErrorCode::NoFileNameError, "no file name was set");
    return;
  }

  vtkImageData* input = this->GetImageDataInput();
  if (!input)
  {
    fail(vtkErrorCode::UnknownError, "the input is not a vtkImageData");
    return;
  }
  int extent[6];
  input->GetExtent(extent);
  std::string problem = CheckExtent(extent);
  if (!problem.empty())
  {
    fail(vtkErrorCode::UnknownError, problem);
    return;
  }
  // The array chosen with SetInputArrayToProcess(0, ...), else the active point scalars.
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  vtkInformationVector* chosen = this->GetInformation()->Get(INPUT_ARRAYS_TO_PROCESS());
  if (chosen && chosen->GetNumberOfInformationObjects() > 0)
  {
    int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
    vtkDataArray* array = this->GetInputArrayToProcess(0, input, association);
    if (!array || association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
    {
      fail(vtkErrorCode::UnknownError, "the chosen array is not a point array of the input");
      return;
    }
    scalars = array;
  }
  const vtkIdType width = static_cast<vtkIdType>(extent[1]) - extent[0] + 1;
  const vtkIdType height = static_cast<vtkIdType>(extent[3]) - extent[2] + 1;
  problem = CheckScalars(scalars, width, height);
  if (!problem.empty())
  {
    fail(vtkErrorCode::UnknownError, problem);
    return;
  }
  if (this->Tiled &&
    (this->TileSize[0] < 1 || this->TileSize[1] < 1 || this->TileSize[0] > 65536 ||
      this->TileSize[1] > 65536))
  {
    fail(vtkErrorCode::UnknownError, "the tile size must be in [1, 65536]");
    return;
  }
  std::error_code directoryError;
  if (fs::is_directory(fs::path(fileName), directoryError))
  {
    fail(vtkErrorCode::CannotOpenFileError, "the path is a directory");
    return;
  }

  const Imath::Box2i dataWindow(Imath::V2i(extent[0], extent[2]), Imath::V2i(extent[1], extent[3]));
  const Imath::Box2i displayWindow = DisplayWindowOf(this->DisplayWindow, dataWindow);
  const int scalarType = scalars->GetDataType();
  const Imf::PixelType pixelType = scalarType == VTK_UNSIGNED_INT ? Imf::UINT
    : this->PixelType == PIXEL_TYPE_HALF                          ? Imf::HALF
                                                                  : Imf::FLOAT;

  fs::path temporary;
  bool haveTemporary = false;
  try
  {
    // Convert first: a bad_alloc here must not leave a temporary file behind.
    PixelBuffers buffers;
    const char* base = PixelData(scalars, pixelType, buffers);
    this->UpdateProgress(0.25);

    Imf::Header header(displayWindow, dataWindow, 1.0f, Imath::V2f(0.0f, 0.0f), 1.0f,
      Imf::INCREASING_Y, static_cast<Imf::Compression>(this->Compression));
    Imf::FrameBuffer frameBuffer;
    AddChannels(
      header, frameBuffer, pixelType, base, scalars->GetNumberOfComponents(), dataWindow, width);
    if (this->Tiled)
    {
      header.setTileDescription(Imf::TileDescription(static_cast<unsigned int>(this->TileSize[0]),
        static_cast<unsigned int>(this->TileSize[1]), Imf::ONE_LEVEL));
    }

    std::string error;
    if (!CreateTemporaryFile(fs::path(fileName), temporary, error))
    {
      fail(vtkErrorCode::CannotOpenFileError,
        "cannot create a file in the target directory: " + error);
      return;
    }
    haveTemporary = true;
    if (!WriteImage(temporary, header, frameBuffer, this->Tiled != 0, static_cast<int>(height),
          this->NumberOfThreads))
    {
      this->SetErrorCode(vtkErrorCode::OutOfDiskSpaceError);
      throw std::runtime_error("writing the temporary file failed (disk full?)");
    }
    this->UpdateProgress(0.9);
    ReplaceTarget(temporary, fs::path(fileName));
    haveTemporary = false;
  }
  catch (const std::bad_alloc&)
  {
    fail(vtkErrorCode::UnknownError, "out of memory");
  }
  catch (const Iex::EnospcExc& e) // the file system is full
  {
    fail(vtkErrorCode::OutOfDiskSpaceError, e.what());
  }
  catch (const Iex::EfbigExc& e) // the file is over the process's size limit (RLIMIT_FSIZE)
  {
    fail(vtkErrorCode::OutOfDiskSpaceError, e.what());
  }
  catch (const Iex::EdquotExc& e) // the user's quota is spent
  {
    fail(vtkErrorCode::OutOfDiskSpaceError, e.what());
  }
  catch (const std::exception& e)
  {
    // Keep a more specific code set just before throwing (OutOfDiskSpaceError).
    const unsigned long code = this->GetErrorCode();
    fail(
      code != vtkErrorCode::NoError ? code : static_cast<unsigned long>(vtkErrorCode::UnknownError),
      e.what());
  }
  catch (...)
  {
    fail(vtkErrorCode::UnknownError, "unknown exception from OpenEXR");
  }
  if (haveTemporary)
  {
    std::error_code ec;
    fs::remove(temporary, ec);
  }
  this->UpdateProgress(1.0);
}

//------------------------------------------------------------------------------
void vtkOpenEXRWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "PixelType: " << this->GetPixelTypeAsString() << "\n";
  os << indent << "Compression: " << this->GetCompressionAsString() << "\n";
  os << indent << "DisplayWindow: " << this->DisplayWindow[0] << " " << this->DisplayWindow[1]
     << " " << this->DisplayWindow[2] << " " << this->DisplayWindow[3] << "\n";
  os << indent << "Tiled: " << (this->Tiled ? "On" : "Off") << "\n";
  os << indent << "TileSize: " << this->TileSize[0] << " " << this->TileSize[1] << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}

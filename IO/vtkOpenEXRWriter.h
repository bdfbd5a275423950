// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOpenEXRWriter
 * @brief   write a vtkImageData slice to a single-part OpenEXR (.exr) file
 *
 * vtkOpenEXRWriter writes the point scalars of its vtkImageData input to a flat, single-part
 * OpenEXR file, scanline or tiled: the point array chosen with SetInputArrayToProcess(0, ...)
 * when one was chosen (ParaView's "Scalars"), else the active scalars. The channels follow the
 * number of components: 1 -> Y, 2 -> Y, A, 3 -> R, G, B and 4 -> R, G, B, A.
 *
 * Scalar types. float and double scalars are written as HALF or FLOAT channels (PixelType,
 * default float); double is first rounded to float. Float output of float input is bit-exact,
 * including NaN payloads, infinities and subnormals. Half output clamps: every finite value of
 * magnitude above 65504 (the largest half) is written as +/-65504, so finite input never becomes
 * Inf; +/-Inf input stays +/-Inf. Within the range, Imath's float-to-half conversion rounds to
 * nearest even: magnitudes up to 2^-25 become +/-0 (smaller magnitudes become half subnormals),
 * and NaN stays NaN (the payload keeps its top ten mantissa bits, so NaNs that came from half
 * survive). unsigned
 * int scalars are written losslessly as UINT channels whatever PixelType says. Any other scalar
 * type is refused with an error.
 *
 * Geometry. Structured index (i, j) of the input becomes pixel (i, j) of the file: the data
 * window is the x and y range of the input extent, so an extent that does not start at 0 gives
 * a data window that does not start at (0, 0). Nothing is flipped. The input must be a single
 * z slice (extent[4] == extent[5]); a volume is refused with an error rather than silently
 * truncated. Spacing and origin are not stored. The display window equals the data window
 * unless SetDisplayWindow() was given a non-empty window.
 *
 * Speed. Float input written as FLOAT and unsigned int input are handed to OpenEXR without a
 * copy, and chunks are compressed on several threads (NumberOfThreads).
 *
 * Safety. The file is written to a new temporary file in the target's directory and renamed
 * over the target only once it is complete, so a failed write never leaves a truncated file
 * and never damages an existing one. Every failure is reported with vtkErrorMacro, sets the
 * error code (GetErrorCode()) and makes Write() return 0.
 */

#ifndef vtkOpenEXRWriter_h
#define vtkOpenEXRWriter_h

#include "vtkIOOpenEXRModule.h" // For export macro
#include "vtkWriter.h"

class vtkImageData;

class VTKIOOPENEXR_EXPORT vtkOpenEXRWriter : public vtkWriter
{
public:
  static vtkOpenEXRWriter* New();
  vtkTypeMacro(vtkOpenEXRWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Channel storage for floating-point input. The values are OpenEXR's own codes.
   */
  enum PixelTypes
  {
    PIXEL_TYPE_HALF = 1,
    PIXEL_TYPE_FLOAT = 2
  };

  /**
   * Compression methods, with OpenEXR's own codes. NONE, RLE, ZIPS, ZIP and PIZ are lossless.
   * PXR24 rounds float channels to 24 bits; B44 and B44A are lossy for half channels only
   * (float channels are stored uncompressed); DWAA and DWAB are lossy.
   */
  enum Compressions
  {
    COMPRESSION_NONE = 0,
    COMPRESSION_RLE = 1,
    COMPRESSION_ZIPS = 2,
    COMPRESSION_ZIP = 3,
    COMPRESSION_PIZ = 4,
    COMPRESSION_PXR24 = 5,
    COMPRESSION_B44 = 6,
    COMPRESSION_B44A = 7,
    COMPRESSION_DWAA = 8,
    COMPRESSION_DWAB = 9
  };

  ///@{
  /**
   * Name of the file to write.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Channel type for float and double input: PIXEL_TYPE_HALF or PIXEL_TYPE_FLOAT (default).
   * Ignored for unsigned int input, which is always written as UINT.
   */
  vtkSetClampMacro(PixelType, int, PIXEL_TYPE_HALF, PIXEL_TYPE_FLOAT);
  vtkGetMacro(PixelType, int);
  void SetPixelTypeToHalf() { this->SetPixelType(PIXEL_TYPE_HALF); }
  void SetPixelTypeToFloat() { this->SetPixelType(PIXEL_TYPE_FLOAT); }
  const char* GetPixelTypeAsString();
  ///@}

  ///@{
  /**
   * Compression method, one of the Compressions values. Default COMPRESSION_ZIP (lossless,
   * 16-line blocks, read by every OpenEXR implementation).
   */
  vtkSetClampMacro(Compression, int, COMPRESSION_NONE, COMPRESSION_DWAB);
  vtkGetMacro(Compression, int);
  void SetCompressionToNone() { this->SetCompression(COMPRESSION_NONE); }
  void SetCompressionToRLE() { this->SetCompression(COMPRESSION_RLE); }
  void SetCompressionToZips() { this->SetCompression(COMPRESSION_ZIPS); }
  void SetCompressionToZip() { this->SetCompression(COMPRESSION_ZIP); }
  void SetCompressionToPiz() { this->SetCompression(COMPRESSION_PIZ); }
  void SetCompressionToPxr24() { this->SetCompression(COMPRESSION_PXR24); }
  void SetCompressionToB44() { this->SetCompression(COMPRESSION_B44); }
  void SetCompressionToB44A() { this->SetCompression(COMPRESSION_B44A); }
  void SetCompressionToDwaa() { this->SetCompression(COMPRESSION_DWAA); }
  void SetCompressionToDwab() { this->SetCompression(COMPRESSION_DWAB); }
  const char* GetCompressionAsString();
  ///@}

  ///@{
  /**
   * Display window [xmin, xmax, ymin, ymax] (VTK extent order). An empty window (xmin > xmax
   * or ymin > ymax, the default [0, -1, 0, -1]) means "the same as the data window".
   */
  vtkSetVector4Macro(DisplayWindow, int);
  vtkGetVector4Macro(DisplayWindow, int);
  ///@}

  ///@{
  /**
   * Write a tiled file (one resolution level) instead of a scanline file. Default off.
   */
  vtkSetMacro(Tiled, vtkTypeBool);
  vtkGetMacro(Tiled, vtkTypeBool);
  vtkBooleanMacro(Tiled, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Tile width and height in pixels for tiled files, each in [1, 65536]. Default 64 x 64.
   */
  vtkSetVector2Macro(TileSize, int);
  vtkGetVector2Macro(TileSize, int);
  ///@}

  ///@{
  /**
   * Threads that compress the file's chunks, through OpenEXR's global thread pool (which is
   * raised to this size when smaller, never lowered). 0 (default): as many as vtkSMPTools
   * uses; 1: compress on the calling thread. The file's bytes do not depend on it.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /**
   * Write the file. Returns 1 on success and 0 on failure (see GetErrorCode()).
   */
  int Write() override;

  /**
   * The input image, for convenience.
   */
  vtkImageData* GetImageDataInput();

protected:
  vtkOpenEXRWriter();
  ~vtkOpenEXRWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

  char* FileName;
  int PixelType;
  int Compression;
  int DisplayWindow[4];
  vtkTypeBool Tiled;
  int TileSize[2];
  int NumberOfThreads;

private:
  vtkOpenEXRWriter(const vtkOpenEXRWriter&) = delete;
  void operator=(const vtkOpenEXRWriter&) = delete;
};

#endif

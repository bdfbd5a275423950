// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOpenEXRReader
 * @brief   read one flat part of an OpenEXR (.exr) file into a vtkImageData
 *
 * vtkOpenEXRReader reads the full-resolution level of one scanline or tiled part of an
 * OpenEXR 2.x/3.x file (level 0 of a mip-mapped or rip-mapped part). The output is a
 * single-slice image whose point scalars hold the pixels of the selected channels as float
 * (VTK_FLOAT): half values are widened exactly, bit for bit (NaN payloads, infinities and
 * subnormals included), float values are copied, and a UINT channel read among float ones is
 * rounded to the nearest float (exact below 2^24). When every selected channel is UINT the
 * scalars are VTK_UNSIGNED_INT instead, copied exactly.
 *
 * Geometry. Pixel (x, y) of the EXR data window becomes structured index (x, y, 0) of the
 * output: WHOLE_EXTENT is [xmin, xmax, ymin, ymax, 0, 0] of the data window, the spacing is 1
 * and the origin 0. Row 0 of the file is row 0 of the array; nothing is flipped. The display
 * window is available from GetDisplayWindow() after UpdateInformation().
 *
 * Channel selection. The channels of one layer are read ("diffuse.R" is channel R of layer
 * "diffuse"). Set the layer with SetLayer(); by default the unnamed layer is used when it has
 * channels, otherwise the layer of the first channel in the file. Within the layer:
 * - Y with RY and/or BY (luminance/chroma): converted to R, G, B (plus A when present) by
 *   Imf::RgbaInputFile, which reconstructs the chroma and applies the file's chromaticities.
 *   That class reads only the first part of a file and expects 2x2-subsampled chroma (the
 *   layout OpenEXR writes), so luminance/chroma in another part or with other sampling is
 *   refused with an error;
 * - R, G and B: 3 components (4 with A);
 * - Y: 1 component (2 with A);
 * - anything else: the first (at most four) channels in file order, which OpenEXR sorts by
 *   name, for instance Z, or u and v of a "forward" layer.
 * GetChannelNames() lists every channel of the part and GetComponentNames() the channel read
 * into each output component (the array's component names are set to the same strings).
 *
 * Multi-part files. SetPartIndex() selects a part by position and SetPartName() by name (the
 * name wins when it is set). GetNumberOfParts() and GetPartName(int) describe the file after
 * UpdateInformation(). Deep parts are refused with an error. Only the selected part's pixel
 * data is validated, so an intact part of a multi-part file whose other parts are damaged or
 * truncated can still be read; the headers of all parts must be valid.
 *
 * Robustness. Damaged and hostile files must fail cleanly, in time and memory bounded by what
 * the file can actually hold. The header of every part is parsed first with the OpenEXR core C
 * library in strict mode (it was hardened by fuzzing). Images above MaximumImagePixels or
 * MaximumImageBytes are refused. Then the chunk table of the selected part is validated before
 * any pixel memory is allocated: every chunk must lie where the data window puts it and inside
 * the file, and its compressed bytes must be able to decode to the size the header claims (no
 * OpenEXR compression expands a byte into more than a known bound, 1032 for deflate), so a
 * few-hundred-byte file that claims gigabytes is refused at once. The core library then reads
 * and decompresses the chunks on several threads (vtkSMPTools), and the reader unpacks each
 * into the output after checking that its size matches the channel layout; the output is the
 * only full-size buffer. Luminance/chroma files go through the same validation and
 * decompression before Imf::RgbaInputFile reads them (in strips). Only regular files are opened.
 * Channels other than luminance/chroma must not be subsampled. Every failure is reported with
 * vtkErrorMacro (so an ErrorEvent observer sees it), sets the error code (GetErrorCode():
 * vtkErrorCode::FileNotFoundError, FileFormatError, ...) and leaves the output empty: no point data
 * and an empty extent.
 */

#ifndef vtkOpenEXRReader_h
#define vtkOpenEXRReader_h

#include "vtkIOOpenEXRModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include <memory> // For std::unique_ptr

class vtkStringArray;

class VTKIOOPENEXR_EXPORT vtkOpenEXRReader : public vtkImageAlgorithm
{
public:
  static vtkOpenEXRReader* New();
  vtkTypeMacro(vtkOpenEXRReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Name of the file to read.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * Return 3 when the file has a valid OpenEXR header (as parsed by the core library in strict
   * mode), 0 otherwise, following the vtkImageReader2 convention. The pixel data is not checked.
   */
  virtual int CanReadFile(const char* fname);

  /**
   * File extensions and description, as vtkImageReader2 reports them.
   */
  virtual const char* GetFileExtensions() { return ".exr"; }
  virtual const char* GetDescriptiveName() { return "OpenEXR"; }

  ///@{
  /**
   * Index of the part to read in a multi-part file. Default 0. Ignored when PartName is set.
   */
  vtkSetClampMacro(PartIndex, int, 0, VTK_INT_MAX);
  vtkGetMacro(PartIndex, int);
  ///@}

  ///@{
  /**
   * Name of the part to read. When it is set (not null, not empty) it takes precedence over
   * PartIndex; a name that the file does not contain is an error. Default null.
   */
  vtkSetStringMacro(PartName);
  vtkGetStringMacro(PartName);
  ///@}

  ///@{
  /**
   * Layer whose channels are read ("diffuse" selects "diffuse.R", "diffuse.G", ...). Null or
   * empty selects the default layer as described above. Default null.
   */
  vtkSetStringMacro(Layer);
  vtkGetStringMacro(Layer);
  ///@}

  ///@{
  /**
   * Largest decoded image, in bytes (width * height * components * 4), that the reader agrees
   * to allocate.
   * Larger images are refused before any pixel memory is allocated, which bounds the memory a
   * damaged or hostile header can request. Default 4 GiB.
   */
  vtkSetMacro(MaximumImageBytes, vtkTypeUInt64);
  vtkGetMacro(MaximumImageBytes, vtkTypeUInt64);
  ///@}

  ///@{
  /**
   * Largest image, in pixels of the data window, that the reader agrees to read. Larger
   * images are refused, before anything is allocated, with an error that names this limit;
   * raise it explicitly for giant legitimate files. Default 2^28 (268,435,456 pixels: 16384 x
   * 16384).
   */
  vtkSetMacro(MaximumImagePixels, vtkTypeUInt64);
  vtkGetMacro(MaximumImagePixels, vtkTypeUInt64);
  ///@}

  /**
   * Number of parts in the file, 0 if it could not be read. Valid after UpdateInformation().
   */
  int GetNumberOfParts();

  /**
   * Name of part `index` ("" for an unnamed single part), or null when the index is out of
   * range. Valid after UpdateInformation().
   */
  const char* GetPartName(int index);

  /**
   * Index of the part that was actually selected (PartName resolved), -1 if none. Valid after
   * UpdateInformation().
   */
  vtkGetMacro(SelectedPartIndex, int);

  ///@{
  /**
   * Data window and display window of the selected part as [xmin, xmax, ymin, ymax], in the
   * same order as a VTK extent. Both are [0, -1, 0, -1] when no file has been read. Valid
   * after UpdateInformation().
   */
  vtkGetVector4Macro(DataWindow, int);
  vtkGetVector4Macro(DisplayWindow, int);
  ///@}

  /**
   * Full names of every channel of the selected part, in file order. Valid after
   * UpdateInformation().
   */
  vtkStringArray* GetChannelNames();

  /**
   * Name of each output component: the full channel name, or "R", "G", "B" (and "A") for
   * converted luminance/chroma data. Valid after UpdateInformation().
   */
  vtkStringArray* GetComponentNames();

protected:
  vtkOpenEXRReader();
  ~vtkOpenEXRReader() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  char* FileName;
  int PartIndex;
  char* PartName;
  char* Layer;
  vtkTypeUInt64 MaximumImageBytes;
  vtkTypeUInt64 MaximumImagePixels;

  int SelectedPartIndex;
  int DataWindow[4];
  int DisplayWindow[4];

private:
  vtkOpenEXRReader(const vtkOpenEXRReader&) = delete;
  void operator=(const vtkOpenEXRReader&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif

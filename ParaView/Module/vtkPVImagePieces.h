// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVImagePieces
 * @brief   Gathers the pieces of distributed image data back into one image, exactly.
 *
 * ParaView's parallel writer for serial formats (vtkParallelSerialWriter) gathers every rank's
 * piece to the first rank. The gather marshals each piece through VTK's legacy format, which
 * keeps dimensions but not extents, so the pieces arrive all starting at index 0. This filter
 * is both of the writer's helpers:
 *
 * - TAG (the pre-gather helper): the input, shallow-copied, with its extent in a field array;
 * - ASSEMBLE (the post-gather helper, any number of inputs): each input put back at its tagged
 *   extent, and all of them combined into one image over the union of the extents with
 *   vtkImageAppend's PreserveExtents, the tag removed.
 */

#ifndef vtkPVImagePieces_h
#define vtkPVImagePieces_h

#include "vtkImageAlgorithm.h"
#include "vtkParaViewBloomModule.h" // For export macro

class VTKPARAVIEWBLOOM_EXPORT vtkPVImagePieces : public vtkImageAlgorithm
{
public:
  static vtkPVImagePieces* New();
  vtkTypeMacro(vtkPVImagePieces, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    TAG = 0,
    ASSEMBLE = 1
  };
  vtkSetClampMacro(Mode, int, TAG, ASSEMBLE);
  vtkGetMacro(Mode, int);

  /// The field array that carries a piece's extent.
  static const char* GetExtentArrayName() { return "vtkPVImagePieces_Extent"; }

protected:
  vtkPVImagePieces();
  ~vtkPVImagePieces() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Mode = TAG;

private:
  vtkPVImagePieces(const vtkPVImagePieces&) = delete;
  void operator=(const vtkPVImagePieces&) = delete;
};

#endif

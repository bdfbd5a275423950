// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassOperators.h
 * @brief  (private to vtkBloomPass) the GPU form of a chain's operators: each operator's rows
 *         as a small R32F texture (its borders, OP_TABLE), its translation-invariant interior
 *         as constants and uniform weights (OP_PERIODIC), the segments a pass draws along an
 *         axis, and the rows a tile of a fused pass reads.
 *
 * Each is made on first use and kept per operator, by its address: Release() before the
 * chain is rebuilt.
 */

#ifndef vtkBloomPassOperators_h
#define vtkBloomPassOperators_h

#include "vtkBloomPassTypes.h" // For the segments
#include "vtkSmartPointer.h"   // For the textures

#include <map>
#include <string>
#include <vector>

class vtkBloomLinearOperator;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class vtkBloomPassOperators
{
public:
  /**
   * The translation-invariant interior of a vtkBloomLinearOperator: output samples
   * [Begin, End) whose rows repeat with period Period, First advancing by Stride per period
   * (a convolution: period 1, stride 1; a 2:1 resample: 1, 2; a 1:2 resample: 2, 1). It is read
   * from the operator's own rows, in the float precision the GPU uses, so a pass that computes
   * the interior from these constants evaluates exactly the operator's weights.
   */
  struct Interior
  {
    int Begin = 0;
    int End = 0; ///< End == Begin: no interior
    int Period = 0;
    int Stride = 0;
    int Taps = 0;
    int First[2] = { 0, 0 };    ///< First of rows Begin and Begin + 1 (period 2)
    std::vector<float> Weights; ///< Period rows of Taps weights

    static Interior Find(const vtkBloomLinearOperator& op);

    /// The #defines of OP_PERIODIC along `axis` ("X" or "Y"); the weights are uniforms.
    std::string Defines(const char* axis) const;
  };

  /// 112 rows of 16 RGBA float samples (both terms of a fused pass together): 28 KiB of the
  /// 32 KiB of shared memory OpenGL 4.3 grants.
  static constexpr int MaximumTileRows = 112;

  /// The operator's rows as a texture of `context`: row j holds First[j], then the band.
  vtkTextureObject* Texture(vtkOpenGLRenderWindow* context, const vtkBloomLinearOperator& op);
  const Interior& InteriorOf(const vtkBloomLinearOperator& op);
  /**
   * The output samples along one axis: the periodic interior, and the borders by table; with
   * `single`, the whole axis by table. A null operator is the identity.
   */
  std::vector<vtkBloomPassSegment> Segments(
    const vtkBloomLinearOperator* op, int size, bool single);
  /// The most input rows 16 consecutive output rows of `y` read (TILE_ROWS).
  int TileRows(const vtkBloomLinearOperator& y);

  /// Free the textures and forget every operator.
  void Release(vtkWindow* w);

private:
  std::map<const vtkBloomLinearOperator*, vtkSmartPointer<vtkTextureObject>> Textures;
  std::map<const vtkBloomLinearOperator*, Interior> Interiors;
  std::map<const vtkBloomLinearOperator*, int> TileRowCounts;
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassOperators.h

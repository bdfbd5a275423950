// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBloomChain
 * @brief   The linear operators of one bloom evaluation, level by level.
 *
 * A vtkBloomParameters describes a chain (bright pass, pyramid, per-level blur,
 * accumulation, composite); for a given image size that chain is a fixed list of separable
 * vtkBloomLinearOperator passes plus a few point-wise steps. vtkBloomChain::Build turns the
 * parameters into that list once, from the same kernel functions the CPU filters use, so the
 * GLSL render pass (vtkBloomPass) and the CPU path evaluate exactly the same operators: the
 * render pass uploads them as textures and never writes a weight of its own.
 *
 * With levels 0..n-1 (level 0 is the first level of the pyramid, StartLevel below the input):
 *
 *   L_0     = threshold(Source.Y Source.X I)
 *   L_i     = sum_t Down[t].Weight Down[t].Y Down[t].X L_{i-1}   (Karis-weighted if Karis)
 *   Lb_i    = BlurY BlurX L_i                                   (when Blur, else L_i)
 *   CASCADE: A_{n-1} = w_{n-1} Lb_{n-1}, A_i = UpY UpX A_{i+1} + w_i Lb_i,
 *            bloom = Final.Y Final.X A_0
 *   DIRECT:  bloom = sum_i w_i FullY FullX Lb_i                  (levels with w_i != 0)
 *   out     = keep I + Strength Tint bloom, keep = 1 - Strength for LERP, 1 for ADDITIVE.
 *
 * The point-wise values (the threshold, the composite) are not copied here: the evaluators read
 * them from the parameters the chain was built from.
 *
 * An empty level list means that no level fits the image and the bloom is black.
 */

#ifndef vtkBloomChain_h
#define vtkBloomChain_h

#include "vtkBloomLinearOperator.h" // For the operators
#include "vtkFiltersBloomModule.h"  // For export macro

#include <vector>

class vtkBloomParameters;

class VTKFILTERSBLOOM_EXPORT vtkBloomChain
{
public:
  /// Weight * (Y X): one separable term of a two-dimensional step.
  struct Term
  {
    double Weight = 1.0;
    vtkBloomLinearOperator X;
    vtkBloomLinearOperator Y;
  };

  struct Level
  {
    int Size[2] = { 0, 0 };
    double Weight = 1.0;    ///< w_i, vtkBloomParameters::GetLevelWeight(i)
    std::vector<Term> Down; ///< from the previous level; empty for level 0
    bool Karis = false;     ///< combine Down with the Karis average
    bool Blur = false;      ///< false when the level does not contribute or nothing blurs
    Term BlurPass;          ///< all BlurIterations folded into one operator per axis
    Term Up;                ///< CASCADE: level i+1's size to this level's (not on the last)
    Term Full;              ///< DIRECT: this level to the full image size
  };

  /// Build the chain for a width x height image (both >= 1) from the bloom's parameters.
  void Build(vtkBloomParameters* parameters, int width, int height);

  /**
   * The samples of the image, [inMin, inMax] along `axis` (0: x, 1: y), that the bloom of the
   * output samples [outMin, outMax] reads, through every operator of the chain (bands counted
   * whole).
   */
  void GetInputRange(int axis, int outMin, int outMax, int& inMin, int& inMax) const;

  /**
   * This chain becomes `frame` cut to the part [begin, end) of frame's image (a tile of a
   * larger frame with its guard band): every operator's rows for the part's samples of each
   * level (Cut), so that the part's bloom is the frame's bloom wherever the frame's bloom reads
   * only samples of the part (GetInputRange). Each level keeps the samples under the part, and
   * two more on each side; a level 0 that is the image itself keeps the part.
   */
  void Cut(const vtkBloomChain& frame, const int begin[2], const int end[2]);

  int Width = 0;
  int Height = 0;
  bool SourceIsIdentity = true; ///< StartLevel 0: the bright pass reads the image itself
  Term Source;                  ///< full size to level 0 (bilinear fetch)
  std::vector<Level> Levels;
  int AccumulateMode = 0;
  bool FinalIsIdentity = true; ///< CASCADE with StartLevel 0
  Term Final;                  ///< CASCADE: level 0 to the full size
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomChain.h

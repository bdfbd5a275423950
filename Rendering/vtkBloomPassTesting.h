// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassTesting.h
 * @brief  (private to vtk-bloom's tests and benchmarks) switches of vtkBloomPass that no user
 *         sets, and its per-pass GPU profile, kept out of its public header.
 *
 * As VTK's own tests reach internals through private headers: not installed, not wrapped.
 * Each switch keeps its value for the pass's life and applies from the next render.
 */

#ifndef vtkBloomPassTesting_h
#define vtkBloomPassTesting_h

#include "vtkBloomPassTypes.h"       // For the profile's entries
#include "vtkRenderingBloomModule.h" // For export macro

#include <vector> // For the profile

class vtkBloomPass;

class VTKRENDERINGBLOOM_EXPORT vtkBloomPassTesting
{
public:
  /**
   * On (the default), the scene renders into the depth buffer of the framebuffer the pass was
   * called with where the two match (vtkBloomPassDepth::Share); off, the pass always draws the
   * depth after the composite, as it did before: the frame-cost check shows that its counts
   * see that draw, and the benchmarks measure what it cost.
   */
  static void SetShareWindowDepth(vtkBloomPass* pass, bool share);
  static bool GetShareWindowDepth(vtkBloomPass* pass);

  /**
   * Make every compute program fail to build, as a driver's compiler might. A compute variant
   * that does not build is not fatal: the pass warns once and runs that variant's passes as
   * fragment passes, with the same result. Default off.
   */
  static void SetSimulateComputeShaderFailure(vtkBloomPass* pass, bool fail);

  /**
   * A pass of the chain with at most this many output samples runs as one draw (one compute
   * dispatch), its operators evaluated from their tables; a larger pass is drawn in pieces (the
   * operators' periodic interiors and their borders). Both give the same bits (tested). Default
   * -1, automatic: 2^21 on a GPU (every pass of a 1920 x 1080 frame), 0 on a CPU rasterizer
   * (llvmpipe, softpipe, SwiftShader), where a table fetch per tap costs more than a draw; 0:
   * every pass in pieces. Values below -1 are taken as -1. The measurements behind the
   * default: docs/gpu.md.
   */
  static void SetSingleDrawSamples(vtkBloomPass* pass, int samples);

  /**
   * A separable pair of passes (a term's x half into a scratch target, then its y half) that is
   * one draw (SetSingleDrawSamples) of compute shaders runs as one dispatch, whose 16 x 16 work
   * groups sum the source rows they read once, in shared memory. The same sums in the same
   * order, so the same bits (tested); the default chain's 32 dependent dispatches become 11
   * (docs/gpu.md). Default on.
   */
  static void SetFuseSeparablePasses(vtkBloomPass* pass, bool fuse);

  /**
   * Per-pass GPU profile, for benchmarks (off by default). Profiled, every GPU pass of a render
   * (the delegate's scene, the emitters, each pass of the chain and the composite, the depth's
   * write where the scene could not render into the window's depth buffer, the renderer's FXAA)
   * is bracketed by two GL timestamp queries (glQueryCounter with GL_TIMESTAMP, OpenGL 3.3 or
   * ARB_timer_query), and the end of Render() waits for the GPU to read them, so a profiled
   * frame is slower than an unprofiled one: profile in frames that are not timed otherwise.
   * Timestamps rather than GL_TIME_ELAPSED, so that a caller may still time the whole frame with
   * a GL_TIME_ELAPSED query. Off, it costs one test per pass.
   */
  static void SetProfilePasses(vtkBloomPass* pass, bool profile);

  /**
   * Time every chain with two GL timestamp queries, for benchmarks (off by default): the pass's
   * GetLastFrame() then gives, without waiting, the GPU milliseconds of the latest frame whose
   * timestamps have arrived (vtkBloomFrameReport::GetChainMilliseconds). Off, only the frames
   * the bright region's cost is learned from are timed.
   */
  static void SetTimeChains(vtkBloomPass* pass, bool time);

  /// One entry of the profile (vtkBloomPassTypes.h).
  using ProfiledPass = vtkBloomPassProfiledPass;

  /**
   * The entries of the last profiled render, in the order the GPU ran them ("depth" and "fxaa"
   * outside the chain, after the composite); empty when profiling is off.
   */
  static std::vector<ProfiledPass> GetProfile(vtkBloomPass* pass);
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassTesting.h

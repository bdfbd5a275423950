// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file    vtkBloomPieces.h
 * @brief   Internal: input requests that stay exact when the output is asked for by piece.
 *
 * Not installed. Under MPI (ParaView's pvbatch and pvserver), each rank asks the last filter
 * for piece p of N. The streaming executive keeps UPDATE_EXTENT as the extent of all pieces
 * and splits it into piece p only when an algorithm that can produce sub-extents executes
 * (vtkStreamingDemandDrivenPipeline::ExecuteDataStart). A filter that grows its input request
 * by a kernel's support would therefore grow the extent of all pieces, and the producer
 * upstream would then split that request again and give only its piece p, without the
 * support. These two helpers let the filters grow the piece they will compute and ask the
 * input for exactly that extent, as one piece.
 */

#ifndef vtkBloomPieces_h
#define vtkBloomPieces_h

class vtkImageData;
class vtkInformation;

/**
 * Mark `outInfo`'s output as able to produce sub-extents, so that a request for piece p of N
 * executes for piece p's block only (each rank computes its own piece), and return the extent
 * the algorithm will execute for: UPDATE_EXTENT, split into the requested piece as the
 * executive will split it (same split mode, no ghost levels). Call it from
 * RequestUpdateExtent, before the executive's ExecuteDataStart reads the mark.
 */
void vtkBloomExecutionExtent(vtkInformation* outInfo, int extent[6]);

/// Ask the input for exactly `extent`, as piece 0 of 1, so that nothing upstream splits it.
void vtkBloomRequestExactExtent(vtkInformation* inInfo, const int extent[6]);

/**
 * Make `outInfo`'s active-scalar information (which AllocateOutputData allocates by) match the
 * scalars `input` really holds. The information pass copies the input's advertised active
 * scalars, which need not be the array that arrives: ParaView's array selection, for one,
 * hands a filter another array than the one its source advertised.
 */
void vtkBloomMatchOutputScalars(vtkInformation* outInfo, vtkImageData* input);

#endif

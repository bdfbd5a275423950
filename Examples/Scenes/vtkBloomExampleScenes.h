// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file    vtkBloomExampleScenes.h
 * @brief   The emissive example scenes that `vtk-bloom render`, the tests and the README use.
 *
 * Each scene fills a renderer and configures a vtkBloomPass for it (preset, threshold, emitters).
 * They use only the modules of the minimal OSMesa VTK build (no FiltersFlowPaths, no text), so
 * they render headless there as well as under X.
 */

#ifndef vtkBloomExampleScenes_h
#define vtkBloomExampleScenes_h

#include <string>
#include <vector>

class vtkBloomPass;
class vtkRenderer;

/// The scene names, in the order `vtk-bloom render --list` prints them.
std::vector<std::string> vtkBloomExampleSceneNames();

/// One line describing a scene (empty for an unknown name).
std::string vtkBloomExampleSceneDescription(const std::string& name);

/**
 * Populate `renderer` (camera, lights, background, actors) with the named scene and set the
 * pass's parameters and emitters for it. Returns false for an unknown name.
 */
bool vtkBloomBuildExampleScene(const std::string& name, vtkRenderer* renderer, vtkBloomPass* pass);

#endif

// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBloomPassProgramCache.h
 * @brief  (private to vtkBloomPass) GPU programs by the key of their source, kept for the last
 *         few settings only.
 *
 * The chain's programs are specialized to its operators (a table's width is a constant, so
 * that its loop unrolls), so each setting of the parameters has programs of its own. Kept for
 * ever, a user's slider would compile and keep a set for every value it passes. The cache counts
 * generations (one per chain built): EndGeneration() frees the programs that no generation of
 * the last Kept has used, so that going back and forth between a few presets, or the tiles of a
 * screenshot, compiles nothing again, and a sweep holds the programs of its last few steps.
 */

#ifndef vtkBloomPassProgramCache_h
#define vtkBloomPassProgramCache_h

#include <map>
#include <string>

template <typename Program>
class vtkBloomPassProgramCache
{
public:
  /// Generations whose programs are kept: a 3 x 3 tiled screenshot and the frame around it.
  static constexpr unsigned int Kept = 12;

  /// The program of `key`, default-made where it is new, marked as used by this generation.
  /// References stay valid until EndGeneration() or Clear() drops their entry.
  Program& operator[](const std::string& key)
  {
    Entry& entry = this->Entries[key];
    entry.Generation = this->Generation;
    return entry.Value;
  }

  void Erase(const std::string& key) { this->Entries.erase(key); }

  /// Start a new generation; the programs unused for Kept generations go to `release`, then out.
  template <typename Release>
  void EndGeneration(const Release& release)
  {
    ++this->Generation;
    for (auto it = this->Entries.begin(); it != this->Entries.end();)
    {
      if (it->second.Generation + Kept < this->Generation)
      {
        release(it->second.Value);
        it = this->Entries.erase(it);
      }
      else
      {
        ++it;
      }
    }
  }

  /// Every program to `release`, then none.
  template <typename Release>
  void Clear(const Release& release)
  {
    for (auto& entry : this->Entries)
    {
      release(entry.second.Value);
    }
    this->Entries.clear();
  }

private:
  struct Entry
  {
    Program Value{};
    unsigned int Generation = 0;
  };
  std::map<std::string, Entry> Entries;
  unsigned int Generation = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkBloomPassProgramCache.h

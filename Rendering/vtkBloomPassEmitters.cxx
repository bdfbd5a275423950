// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBloomPass's emitter API (selective bloom): the emitters, the scalar-range emitter and the
// keys it records. How the emission is written is vtkBloomPassEmission's.
#include "vtkBloomPass.h"

#include "vtkActor.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationObjectBaseKey.h"
#include "vtkLookupTable.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkPropCollection.h"

#include <algorithm>
#include <cmath>

vtkInformationKeyMacro(vtkBloomPass, EMITTER_SOURCE, ObjectBase);
vtkInformationKeyRestrictedMacro(vtkBloomPass, EMITTER_SCALAR_RANGE, DoubleVector, 2);

namespace
{
// The table of a scalar-range emitter drawn with vertex colours: `colours` sampled over the
// range, black outside it. The mapper may still colour by texture, where a value exactly at an
// end of the table's range samples the edge between the range and the black outside it: the
// table spans the range widened by a hair, so that both ends themselves glow.
vtkSmartPointer<vtkLookupTable> vtkBloomPassRangeTable(
  vtkScalarsToColors* colours, const double range[2])
{
  const double hair =
    1e-6 * std::max({ range[1] - range[0], std::abs(range[0]), std::abs(range[1]), 1e-300 });
  const double lo = range[0] - hair, hi = range[1] + hair;
  const int n = 256;
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(n);
  table->SetTableRange(lo, hi);
  // Vectors are mapped as the actor maps them (magnitude or one component).
  table->SetVectorMode(colours->GetVectorMode());
  table->SetVectorComponent(colours->GetVectorComponent());
  for (int i = 0; i < n; ++i)
  {
    const double value = lo + (hi - lo) * (i + 0.5) / n;
    double rgb[3];
    colours->GetColor(value, rgb);
    table->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
  }
  table->SetUseBelowRangeColor(true);
  table->SetBelowRangeColor(0.0, 0.0, 0.0, 1.0);
  table->SetUseAboveRangeColor(true);
  table->SetAboveRangeColor(0.0, 0.0, 0.0, 1.0);
  return table;
}
}

//------------------------------------------------------------------------------
void vtkBloomPass::AddEmitter(vtkProp* prop)
{
  if (prop && !this->Emitters->IsItemPresent(prop))
  {
    this->Emitters->AddItem(prop);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkActor* vtkBloomPass::AddScalarRangeEmitter(vtkActor* actor, double low, double high)
{
  const double range[2] = { low, high };
  vtkSmartPointer<vtkActor> emitter = vtkBloomPass::CreateScalarRangeEmitter(actor, range);
  this->AddEmitter(emitter); // the collection holds it
  return emitter;
}

//------------------------------------------------------------------------------
void vtkBloomPass::RemoveEmitter(vtkProp* prop)
{
  if (prop && this->Emitters->IsItemPresent(prop))
  {
    this->Emitters->RemoveItem(prop);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBloomPass::RemoveAllEmitters()
{
  if (this->Emitters->GetNumberOfItems() > 0)
  {
    this->Emitters->RemoveAllItems();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkActor> vtkBloomPass::CreateScalarRangeEmitter(
  vtkActor* actor, const double range[2])
{
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  vtkScalarsToColors* colours = mapper ? mapper->GetLookupTable() : nullptr;
  if (!mapper || !colours || !range || !(range[0] <= range[1]))
  {
    return nullptr;
  }
  vtkSmartPointer<vtkMapper> copy;
  copy.TakeReference(mapper->NewInstance());
  // Not ShallowCopy: the OpenGL mapper's copies its deprecated shader-code members too.
  if (mapper->GetNumberOfInputConnections(0) > 0)
  {
    copy->SetInputConnection(mapper->GetInputConnection(0, 0));
  }
  else
  {
    copy->SetInputDataObject(mapper->GetInputDataObject(0, 0));
  }
  copy->SetScalarVisibility(true);
  copy->SetScalarMode(mapper->GetScalarMode());
  copy->SetArrayAccessMode(mapper->GetArrayAccessMode());
  copy->SetArrayId(mapper->GetArrayId());
  copy->SetArrayName(mapper->GetArrayName());
  copy->SetArrayComponent(mapper->GetArrayComponent());
  copy->SetColorMode(mapper->GetColorMode());
  copy->SetInterpolateScalarsBeforeMapping(mapper->GetInterpolateScalarsBeforeMapping());

  auto emitter = vtkSmartPointer<vtkActor>::New();
  emitter->ShallowCopy(actor);
  emitter->SetMapper(copy);
  const bool textured = mapper->GetInterpolateScalarsBeforeMapping() &&
    mapper->GetScalarVisibility() && !colours->UsingLogScale();
  if (textured)
  {
    // The actor's own colours through the same texture coordinates; the range is tested per
    // fragment (vtkBloomPassEmission), so the pass can write it in the actor's own render.
    vtkSmartPointer<vtkScalarsToColors> table;
    table.TakeReference(colours->NewInstance());
    table->DeepCopy(colours);
    copy->SetLookupTable(table);
    copy->SetScalarRange(mapper->GetScalarRange());
    copy->SetUseLookupTableScalarRange(mapper->GetUseLookupTableScalarRange());
    vtkNew<vtkInformation> keys;
    keys->Set(vtkBloomPass::EMITTER_SOURCE(), actor);
    keys->Set(vtkBloomPass::EMITTER_SCALAR_RANGE(), range, 2);
    emitter->SetPropertyKeys(keys);
  }
  else
  {
    copy->SetLookupTable(vtkBloomPassRangeTable(colours, range));
    copy->SetScalarRange(copy->GetLookupTable()->GetRange());
  }
  return emitter;
}

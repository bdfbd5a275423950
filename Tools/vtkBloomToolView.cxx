// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// vtk-bloom view: a dataset or example scene in an interactive X window, with the bloom's
// parameters on sliders and keys. Built only where VTK has widgets and text (the X build).
#include "vtkBloomExampleScenes.h"
#include "vtkBloomParameters.h"
#include "vtkBloomPass.h"
#include "vtkBloomToolImageIO.h"
#include "vtkBloomToolRender.h"
#include "vtkBloomVTKCompat.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkImageData.h>
#include <vtkInteractorEventRecorder.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPNGWriter.h>
#include <vtkProperty2D.h>
#include <vtkRenderPass.h>
#include <vtkRenderState.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSliderRepresentation2D.h>
#include <vtkSliderWidget.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

// Last: Xlib defines macros (Status, Bool, None, True, False) that VTK's headers use as names.
#include <X11/Xlib.h>
#undef Status
#undef Bool
#undef None
#undef True
#undef False

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>

namespace vtkBloomTool
{
namespace
{
//------------------------------------------------------------------------------
// A pass that times its delegate, with glFinish on both sides so the time is the GPU's too.
class vtkBloomToolTimedPass : public vtkRenderPass
{
public:
  static vtkBloomToolTimedPass* New();
  vtkTypeMacro(vtkBloomToolTimedPass, vtkRenderPass);

  void SetDelegate(vtkRenderPass* pass) { this->Delegate = pass; }
  double GetMilliseconds() const { return this->Milliseconds; }

  void Render(const vtkRenderState* s) override
  {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    this->Delegate->Render(s);
    glFinish();
    this->Milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    this->NumberOfRenderedProps = this->Delegate->GetNumberOfRenderedProps();
  }
  void ReleaseGraphicsResources(vtkWindow* w) override
  {
    this->Delegate->ReleaseGraphicsResources(w);
  }

private:
  vtkSmartPointer<vtkRenderPass> Delegate;
  double Milliseconds = 0.0;
};
vtkStandardNewMacro(vtkBloomToolTimedPass);

const char* const HelpText = "b  bloom on / off\n"
                             "p  next preset\n"
                             "s  save a PNG screenshot\n"
                             "e  save the float frame as EXR\n"
                             "h  this help\n"
                             "q  quit\n"
                             "mouse: rotate, pan (shift), zoom (wheel)";

//------------------------------------------------------------------------------
// Everything the window's callbacks act on.
struct Viewer
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindowInteractor> Interactor;
  vtkNew<vtkBloomPass> Pass;
  vtkNew<vtkRenderStepsPass> Steps;
  vtkNew<vtkBloomToolTimedPass> TimedBloom;
  vtkNew<vtkBloomToolTimedPass> TimedScene;
  vtkNew<vtkTextActor> Status;
  vtkNew<vtkTextActor> Help;
  vtkNew<vtkSliderWidget> Sliders[3];
  RenderOptions Options;
  ErrorCollector Errors;
  bool Bloom = true;
  int Preset = 0; ///< 0: the parameters the view began with (Initial), i: preset i - 1
  vtkNew<vtkBloomParameters> Initial;

  std::string PresetName() const
  {
    return this->Preset == 0 ? std::string("as started")
                             : vtkBloomParameters::GetPresetNames()[this->Preset - 1];
  }
  int Snapshots = 0;

  void AddSlider(int index, const char* title, double lo, double hi, double value, double y)
  {
    vtkNew<vtkSliderRepresentation2D> slider;
    slider->SetMinimumValue(lo);
    slider->SetMaximumValue(hi);
    slider->SetValue(value);
    slider->SetTitleText(title);
    slider->GetPoint1Coordinate()->SetCoordinateSystemToNormalizedDisplay();
    slider->GetPoint1Coordinate()->SetValue(0.70, y);
    slider->GetPoint2Coordinate()->SetCoordinateSystemToNormalizedDisplay();
    slider->GetPoint2Coordinate()->SetValue(0.95, y);
    slider->SetSliderLength(0.03);
    slider->SetSliderWidth(0.03);
    slider->SetTubeWidth(0.005);
    slider->SetLabelHeight(0.025);
    slider->SetTitleHeight(0.025);
    for (vtkProperty2D* p : { slider->GetSliderProperty(), slider->GetTubeProperty(),
           slider->GetCapProperty(), slider->GetSelectedProperty() })
    {
      p->SetColor(0.6, 0.6, 0.6);
    }
    slider->GetTitleProperty()->SetColor(0.7, 0.7, 0.7);
    slider->GetLabelProperty()->SetColor(0.7, 0.7, 0.7);
    vtkSliderWidget* widget = this->Sliders[index];
    widget->SetInteractor(this->Interactor);
    widget->SetRepresentation(slider);
    widget->SetAnimationModeToJump();
    widget->EnabledOn();
    vtkNew<vtkCallbackCommand> changed;
    changed->SetClientData(this);
    changed->SetCallback([](vtkObject*, unsigned long, void* self, void*)
      { static_cast<Viewer*>(self)->SlidersChanged(); });
    widget->AddObserver(vtkCommand::InteractionEvent, changed);
  }

  double SliderValue(int index)
  {
    return vtkSliderRepresentation2D::SafeDownCast(this->Sliders[index]->GetRepresentation())
      ->GetValue();
  }

  void SyncSliders()
  {
    vtkBloomParameters* p = this->Pass->GetParameters();
    const double values[3] = { p->GetThreshold(), p->GetStrength(),
      static_cast<double>(p->GetNumberOfLevels()) };
    for (int i = 0; i < 3; ++i)
    {
      vtkSliderRepresentation2D::SafeDownCast(this->Sliders[i]->GetRepresentation())
        ->SetValue(values[i]);
    }
  }

  void SlidersChanged()
  {
    vtkBloomParameters* p = this->Pass->GetParameters();
    p->SetThreshold(this->SliderValue(0));
    p->SetStrength(this->SliderValue(1));
    p->SetNumberOfLevels(static_cast<int>(std::lround(this->SliderValue(2))));
  }

  void UpdateStatus()
  {
    std::ostringstream text;
    text.setf(std::ios::fixed);
    text.precision(2);
    if (this->Bloom)
    {
      text << "bloom " << this->PresetName() << ": "
           << std::max(
                0.0, this->TimedBloom->GetMilliseconds() - this->TimedScene->GetMilliseconds())
           << " ms / frame (scene " << this->TimedScene->GetMilliseconds() << " ms)";
    }
    else
    {
      text << "bloom off (scene " << this->TimedScene->GetMilliseconds() << " ms)";
    }
    text << "   h: help";
    this->Status->SetInput(text.str().c_str());
  }

  void Key(const std::string& key)
  {
    if (key == "b")
    {
      this->Bloom = !this->Bloom;
      this->Renderer->SetPass(this->Bloom ? static_cast<vtkRenderPass*>(this->TimedBloom)
                                          : static_cast<vtkRenderPass*>(this->TimedScene));
    }
    else if (key == "p")
    {
      // The presets vtkBloomParameters names, then back to the parameters the view began with.
      const int count = static_cast<int>(vtkBloomParameters::GetPresetNames().size());
      this->Preset = (this->Preset + 1) % (count + 1);
      if (this->Preset == 0)
      {
        this->Pass->GetParameters()->DeepCopy(this->Initial);
      }
      else
      {
        this->Pass->SetPreset(this->PresetName().c_str());
      }
      this->SyncSliders();
    }
    else if (key == "s")
    {
      vtkNew<vtkWindowToImageFilter> grab;
      grab->SetInput(this->Window);
      grab->ReadFrontBufferOff();
      vtkNew<vtkPNGWriter> writer;
      writer->SetInputConnection(grab->GetOutputPort());
      const std::string path = this->NextSnapshot(".png");
      writer->SetFileName(path.c_str());
      writer->Write();
      std::cerr << "vtk-bloom: saved " << path << "\n";
    }
    else if (key == "e")
    {
      vtkNew<vtkImageData> image;
      if (this->Bloom)
      {
        this->Pass->ReadResultImage(image);
      }
      else
      {
        this->Pass->ReadSceneImage(image);
      }
      const std::string path = this->NextSnapshot(".exr");
      const int* size = this->Window->GetSize();
      const int displayWindow[4] = { 0, size[0] - 1, 0, size[1] - 1 };
      ProgressBar quiet;
      try
      {
        WriteOutput(TopRowFirst(image), displayWindow, path, 1.0, this->Errors, quiet);
        std::cerr << "vtk-bloom: saved " << path << "\n";
      }
      catch (const RunError& e)
      {
        std::cerr << "vtk-bloom: error: " << e.Message << "\n";
      }
    }
    else if (key == "h")
    {
      this->Help->SetVisibility(!this->Help->GetVisibility());
    }
    else if (key == "q" || key == "Escape")
    {
      this->Interactor->TerminateApp();
      return;
    }
    this->Window->Render();
  }

  std::string NextSnapshot(const char* extension)
  {
    char number[16];
    std::snprintf(number, sizeof(number), "-%03d", this->Snapshots++);
    return this->Options.SnapshotPrefix + number + extension;
  }
};

//------------------------------------------------------------------------------
// Trackball camera, but the keys are the viewer's (the default style's e, s, p, w and 3 would
// exit or change every actor's representation).
class vtkBloomToolViewStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static vtkBloomToolViewStyle* New();
  vtkTypeMacro(vtkBloomToolViewStyle, vtkInteractorStyleTrackballCamera);
  void OnChar() override
  {
    const char* keySym = this->Interactor->GetKeySym();
    std::string key = keySym ? keySym : "";
    if (key.size() != 1 && key != "Escape")
    {
      key = std::string(1, this->Interactor->GetKeyCode());
    }
    this->Target->Key(key);
  }
  Viewer* Target = nullptr;
};
vtkStandardNewMacro(vtkBloomToolViewStyle);
}

//------------------------------------------------------------------------------
int View(const std::string& input, const RenderOptions& options, const std::string& events)
{
  const char* display = std::getenv("DISPLAY");
  Display* connection = display && *display ? XOpenDisplay(display) : nullptr;
  if (!connection)
  {
    throw RunError{ std::string("vtk-bloom view needs an X display, and ") +
      (display && *display ? "DISPLAY=" + std::string(display) + " cannot be opened"
                           : "DISPLAY is not set") +
      "; use 'vtk-bloom render " + input + " OUT.png' to write an image without one" };
  }
  XCloseDisplay(connection);
  RequireOpenGLWindow();

  Viewer viewer;
  viewer.Options = options;
  viewer.Window->SetSize(options.Size[0], options.Size[1]);
  viewer.Window->SetMultiSamples(4); // anti-aliased: the pass keeps the samples
  viewer.Window->SetWindowName(("vtk-bloom view " + input).c_str());
  viewer.Window->AddRenderer(viewer.Renderer);
  viewer.Interactor->SetRenderWindow(viewer.Window);
  vtkNew<vtkBloomToolViewStyle> style;
  style->Target = &viewer;
  viewer.Interactor->SetInteractorStyle(style);
  viewer.Errors.Watch(viewer.Window);
  viewer.Errors.Watch(viewer.Pass);

  viewer.Pass->SetDelegatePass(viewer.TimedScene);
  viewer.TimedScene->SetDelegate(viewer.Steps);
  viewer.TimedBloom->SetDelegate(viewer.Pass);
  viewer.Pass->SetFloatPrecision(
    options.Precision == 32 ? vtkBloomPass::FLOAT32 : vtkBloomPass::FLOAT16);
  viewer.Pass->CaptureResultOn();
  viewer.Renderer->SetPass(viewer.TimedBloom);
  if (!options.Bloom)
  {
    viewer.Bloom = false;
    viewer.Renderer->SetPass(viewer.TimedScene);
  }

  DataScene scene;
  if (IsDatasetPath(input))
  {
    const DatasetFiles files = ResolveDataset(input);
    ErrorCollector errors;
    scene.Build(ReadDataset(files.Files[0], errors), files.Files[0], options.Data, viewer.Renderer,
      viewer.Pass);
    const std::string warning = scene.EmitWarning();
    if (!warning.empty())
    {
      std::cerr << "vtk-bloom: warning: " << warning << "\n";
    }
  }
  else if (!vtkBloomBuildExampleScene(input, viewer.Renderer, viewer.Pass))
  {
    throw UsageError{ "unknown scene '" + input + "' (see render --list), and not a dataset file" };
  }
  else
  {
    TurnCamera(viewer.Renderer, options.Data);
  }
  options.ConfigureBloom(viewer.Pass);
  viewer.Initial->DeepCopy(viewer.Pass->GetParameters());

  viewer.Status->GetTextProperty()->SetFontSize(14);
  viewer.Status->GetTextProperty()->SetColor(0.75, 0.75, 0.75);
  viewer.Status->SetDisplayPosition(10, 10);
  viewer.Renderer->AddViewProp(viewer.Status);
  viewer.Help->SetInput(HelpText);
  viewer.Help->GetTextProperty()->SetFontSize(14);
  viewer.Help->GetTextProperty()->SetColor(0.75, 0.75, 0.75);
  viewer.Help->GetTextProperty()->SetVerticalJustificationToTop();
  viewer.Help->GetPositionCoordinate()->SetCoordinateSystemToNormalizedDisplay();
  viewer.Help->GetPositionCoordinate()->SetValue(0.02, 0.95);
  viewer.Help->SetVisibility(false);
  viewer.Renderer->AddViewProp(viewer.Help);

  viewer.Interactor->Initialize();
  vtkBloomParameters* p = viewer.Pass->GetParameters();
  // vtkSliderRepresentation2D puts the value above the tube and the title below it, each
  // about 0.05 of the height away with text 0.025 high: 0.16 between tubes keeps a value clear
  // of the title above it, and 0.10 under the lowest keeps its title inside the window.
  viewer.AddSlider(0, "threshold", 0.0, 5.0, p->GetThreshold(), 0.42);
  viewer.AddSlider(1, "strength", 0.0, 3.0, p->GetStrength(), 0.26);
  viewer.AddSlider(2, "levels", 1.0, 10.0, p->GetNumberOfLevels(), 0.10);
  vtkNew<vtkCallbackCommand> status;
  status->SetClientData(&viewer);
  status->SetCallback([](vtkObject*, unsigned long, void* self, void*)
    { static_cast<Viewer*>(self)->UpdateStatus(); });
  viewer.Renderer->AddObserver(vtkCommand::EndEvent, status);
  viewer.Window->Render();
  viewer.Errors.ThrowIfAny("view failed:");

  if (!events.empty())
  {
    // Tests: play a recorded event log (vtkInteractorEventRecorder format), then exit.
    std::ifstream in(events);
    if (!in)
    {
      throw RunError{ "cannot read the event log " + events };
    }
    const std::string log((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    vtkNew<vtkInteractorEventRecorder> recorder;
    recorder->SetInteractor(viewer.Interactor);
    recorder->ReadFromInputStringOn();
    recorder->SetInputString(log.c_str());
    recorder->Play();
    recorder->Off();
  }
  else
  {
    viewer.Interactor->Start();
  }
  viewer.Errors.ThrowIfAny("view failed:");
  viewer.Window->Finalize();
  return 0;
}
}

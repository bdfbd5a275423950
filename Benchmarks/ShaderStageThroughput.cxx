// SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
// SPDX-License-Identifier: BSD-3-Clause
// The same full-screen work as a fragment-shader pass and as a compute dispatch, timed by
// the GPU (GL_TIME_ELAPSED, median of FRAMES runs): a 1-tap (a copy) and a 9-tap horizontal
// filter of an RGBA16F image into another, the kind of pass vtkBloomPass's chain is made of;
// then the copy into an RGBA8 texture (a window's colour buffer, where the composite writes)
// as fragments, as a blit and as a compute pass, whose outputs must be the same bytes.
// It measures what bounds a chain of fragment passes on a GPU whose fragment shading runs on
// part of the chip only (an NVIDIA H100: docs/gpu.md). Last, the CPU's cost of a small
// compute dispatch (64 x 64) and of each state change vtkBloomPass's chain makes around one
// (the barrier, the image and texture binds, the program, the unbinds, a dozen uniforms),
// added one at a time: the submission's CPU time per dispatch over 2000 dispatches, and the
// wall time to their completion (issue 37, part 2).
//
//   ShaderStageThroughput [WIDTH HEIGHT [FRAMES]]      (default 3840 2160 50)
//
// It needs OpenGL 4.3 (compute shaders); it prints a markdown table, or says why not.
#include "vtkBloomFrameStatistics.h"

#include "StageThroughputCS.h"
#include "StageThroughputFS.h"
#include "StageThroughputVS.h"

#include "vtkBloomVTKCompat.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderWindow.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace
{
GLuint Compile(GLenum stage, const std::string& text)
{
  const GLuint shader = glCreateShader(stage);
  const char* source = text.c_str();
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok)
  {
    char log[2048];
    glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
    std::fprintf(stderr, "shader: %s\n", log);
  }
  return shader;
}

// The shader text with TAPS defined after its #version line.
std::string WithTaps(const char* text, int taps)
{
  std::string s = text;
  const size_t eol = s.find('\n');
  return s.substr(0, eol + 1) + "#define TAPS " + std::to_string(taps) + "\n" + s.substr(eol + 1);
}

GLuint Link(std::vector<GLuint> shaders)
{
  const GLuint program = glCreateProgram();
  for (GLuint s : shaders)
  {
    glAttachShader(program, s);
  }
  glLinkProgram(program);
  for (GLuint s : shaders)
  {
    glDeleteShader(s);
  }
  return program;
}

GLuint Texture(int w, int h, const std::vector<float>* data, GLenum format = GL_RGBA16F)
{
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexStorage2D(GL_TEXTURE_2D, 1, format, w, h);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  if (data)
  {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, data->data());
  }
  return t;
}

// The median GPU time (GL_TIME_ELAPSED) of `work` over `frames` runs, after three warm-ups.
double MedianGPUTime(GLuint query, GLuint source, int frames, const std::function<void()>& work)
{
  std::vector<double> times;
  for (int f = -3; f < frames; ++f)
  {
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, source);
    glBeginQuery(GL_TIME_ELAPSED, query);
    work();
    glEndQuery(GL_TIME_ELAPSED);
    GLuint64 ns = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
    if (f >= 0)
    {
      times.push_back(1e-6 * static_cast<double>(ns));
    }
  }
  return vtkBloomMedian(times);
}

// One full-screen fragment pass of `program` (sampler "source" on unit 0) into `fbo`.
void Draw(GLuint program, GLuint fbo, GLuint vao, int w, int h)
{
  glUseProgram(program);
  glUniform1i(glGetUniformLocation(program, "source"), 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, w, h);
  glBindVertexArray(vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

// The same work as a compute dispatch of `program` into `image` (in `format`).
void Dispatch(GLuint program, GLuint image, GLenum format, int w, int h)
{
  glUseProgram(program);
  glUniform1i(glGetUniformLocation(program, "source"), 0);
  glBindImageTexture(0, image, 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
  glDispatchCompute((w + 15) / 16, (h + 15) / 16, 1);
  glMemoryBarrier(
    GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}
}

// The CPU's cost per dispatch of the chain's state changes, added one at a time (see above).
void DispatchCost(GLuint programs[2])
{
  const int n = 64, count = 2000;
  GLuint images[2] = { Texture(n, n, nullptr), Texture(n, n, nullptr) };
  const char* steps[] = { "dispatch only (program, image, texture bound once)",
    "+ a barrier each (texture fetch, image access)", "+ the image bound each (ping-pong)",
    "+ the source texture bound each (glActiveTexture, glBindTexture)",
    "+ the program switched each (two programs)", "+ image, texture and program unbound after each",
    "+ 12 glUniform calls each" };
  std::printf("\nThe CPU's cost of a %dx%d compute dispatch and the state changes around it, "
              "%d dispatches a row, added one at a time\n\n| each dispatch | submission, CPU "
              "us a dispatch | to completion, us a dispatch |\n|---|---|---|\n",
    n, n, count);
  for (int level = 0; level < 7; ++level)
  {
    glUseProgram(programs[0]);
    glUniform1i(glGetUniformLocation(programs[0], "source"), 0);
    glUniform1i(glGetUniformLocation(programs[1], "source"), 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, images[0]);
    glBindImageTexture(0, images[1], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glFinish();
    const GLint tapsAt = glGetUniformLocation(programs[0], "unused");
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < count; ++i)
    {
      const int from = i % 2, to = 1 - from;
      if (level >= 4)
      {
        glUseProgram(programs[i % 2]);
      }
      if (level >= 3)
      {
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, images[from]);
      }
      if (level >= 2)
      {
        glBindImageTexture(0, images[to], 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
      }
      for (int u = 0; level >= 6 && u < 12; ++u)
      {
        glUniform1i(tapsAt, u); // location -1 (no such uniform): the call, not the value
      }
      glDispatchCompute(n / 16, n / 16, 1);
      if (level >= 1)
      {
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
      }
      if (level >= 5)
      {
        glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        glBindTexture(GL_TEXTURE_2D, 0);
        glUseProgram(0);
      }
    }
    const auto submitted = std::chrono::steady_clock::now();
    glFinish();
    const auto done = std::chrono::steady_clock::now();
    const double us = 1e6 / count;
    std::printf("| %s | %.2f | %.2f |\n", steps[level],
      us * std::chrono::duration<double>(submitted - start).count(),
      us * std::chrono::duration<double>(done - start).count());
  }
  glDeleteTextures(2, images);
}

int main(int argc, char* argv[])
{
  const int w = argc > 2 ? std::atoi(argv[1]) : 3840;
  const int h = argc > 2 ? std::atoi(argv[2]) : 2160;
  const int frames = argc > 3 ? std::atoi(argv[3]) : 50;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(64, 64);
  auto* gl = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!gl)
  {
    std::printf("no OpenGL render window\n");
    return 1;
  }
  gl->Initialize();
  gl->MakeCurrent();
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < 43)
  {
    std::printf("OpenGL %d.%d: no compute shaders\n", major, minor);
    return 0;
  }
  std::vector<float> pixels(static_cast<size_t>(w) * h * 4);
  for (size_t i = 0; i < pixels.size(); ++i)
  {
    pixels[i] = static_cast<float>(i % 97) * 0.01f;
  }
  const GLuint source = Texture(w, h, &pixels);
  const GLuint target = Texture(w, h, nullptr);
  GLuint fbo = 0, vao = 0, query = 0;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
  glGenVertexArrays(1, &vao);
  glGenQueries(1, &query);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  const double mb = 2.0 * 8.0 * w * h * 1e-6; // read once, written once
  std::printf("%dx%d RGBA16F into RGBA16F, GPU time (GL_TIME_ELAPSED), median of %d\n\n| work "
              "| fragment shader | compute shader | fragment / compute | compulsory MB |\n"
              "|---|---|---|---|---|\n",
    w, h, frames);
  for (const int taps : { 1, 9 })
  {
    const GLuint fragment = Link({ Compile(GL_VERTEX_SHADER, StageThroughputVS),
      Compile(GL_FRAGMENT_SHADER, WithTaps(StageThroughputFS, taps)) });
    const GLuint compute = Link({ Compile(GL_COMPUTE_SHADER, WithTaps(StageThroughputCS, taps)) });
    double ms[2];
    std::vector<float> results[2];
    for (int stage = 0; stage < 2; ++stage)
    {
      ms[stage] = MedianGPUTime(query, source, frames,
        [&]()
        {
          if (stage == 0)
          {
            Draw(fragment, fbo, vao, w, h);
          }
          else
          {
            Dispatch(compute, target, GL_RGBA16F, w, h);
          }
        });
      // The last run's output, to check that both stages computed the same thing.
      results[stage].resize(pixels.size());
      glBindTexture(GL_TEXTURE_2D, target);
      glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, results[stage].data());
    }
    if (results[0] != results[1])
    {
      std::printf("the fragment and compute outputs differ\n");
      return 1;
    }
    std::printf("| %d-tap horizontal filter | %.4f ms (%.0f GB/s) | %.4f ms (%.0f GB/s) | %.1f | "
                "%.1f |\n",
      taps, ms[0], mb / ms[0], ms[1], mb / ms[1], ms[0] / ms[1], mb);
    glDeleteProgram(fragment);
    glDeleteProgram(compute);
  }

  // The last step of a composite: the copy into an RGBA8 colour texture (VTK's render
  // framebuffer), as fragments, as glBlitFramebuffer and as a compute pass with imageStore.
  const GLuint colour = Texture(w, h, nullptr, GL_RGBA8);
  GLuint read = 0, draw = 0;
  glGenFramebuffers(1, &read);
  glBindFramebuffer(GL_FRAMEBUFFER, read);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, source, 0);
  glGenFramebuffers(1, &draw);
  glBindFramebuffer(GL_FRAMEBUFFER, draw);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour, 0);
  const GLuint fragment = Link({ Compile(GL_VERTEX_SHADER, StageThroughputVS),
    Compile(GL_FRAGMENT_SHADER, WithTaps(StageThroughputFS, 1)) });
  std::string text = WithTaps(StageThroughputCS, 1);
  text.replace(text.find("rgba16f"), 7, "rgba8");
  const GLuint compute = Link({ Compile(GL_COMPUTE_SHADER, text) });
  const double mb8 = 12.0 * w * h * 1e-6; // 8 bytes read, 4 written a sample
  const char* ways[] = { "fragment shader", "glBlitFramebuffer", "compute shader" };
  std::vector<unsigned char> results[3];
  std::printf("\n%dx%d RGBA16F into RGBA8 (a window's colour texture), median of %d\n\n| copy "
              "| GPU time | GB/s |\n|---|---|---|\n",
    w, h, frames);
  for (int way = 0; way < 3; ++way)
  {
    const double ms = MedianGPUTime(query, source, frames,
      [&]()
      {
        if (way == 0)
        {
          Draw(fragment, draw, vao, w, h);
        }
        else if (way == 1)
        {
          glBindFramebuffer(GL_READ_FRAMEBUFFER, read);
          glBindFramebuffer(GL_DRAW_FRAMEBUFFER, draw);
          glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        }
        else
        {
          Dispatch(compute, colour, GL_RGBA8, w, h);
        }
      });
    results[way].resize(static_cast<size_t>(w) * h * 4);
    glBindTexture(GL_TEXTURE_2D, colour);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, results[way].data());
    std::printf("| %s | %.4f ms | %.0f |\n", ways[way], ms, mb8 / ms);
  }
  if (results[0] != results[1] || results[0] != results[2])
  {
    std::printf("the three RGBA8 outputs differ\n");
    return 1;
  }
  glDeleteProgram(fragment);
  glDeleteProgram(compute);
  GLuint programs[2] = { Link({ Compile(GL_COMPUTE_SHADER, WithTaps(StageThroughputCS, 1)) }),
    Link({ Compile(GL_COMPUTE_SHADER, WithTaps(StageThroughputCS, 9)) }) };
  DispatchCost(programs);
  glDeleteProgram(programs[0]);
  glDeleteProgram(programs[1]);
  glUseProgram(0);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteVertexArrays(1, &vao);
  const GLuint framebuffers[] = { fbo, read, draw };
  glDeleteFramebuffers(3, framebuffers);
  glDeleteQueries(1, &query);
  const GLuint textures[] = { source, target, colour };
  glDeleteTextures(3, textures);
  return 0;
}

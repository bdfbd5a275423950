# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""What a render window's OpenGL context runs on, asked of EGL and OpenGL themselves (imported by
the GPU scripts bloom_gpu_devices.py and bloom_gpu_timing.py, not run).

    from gpu_context import describe
    info = describe(render_window)   # a dict; the context is made current first

Through ctypes, on the libraries the process already holds (glvnd's libEGL.so.1, which VTK's
EGL window loaded): the EGL display's device (EGL_EXT_device_query), its index among
eglQueryDevicesEXT's devices (the index that pvbatch's --displays and
VTK_DEFAULT_EGL_DEVICE_INDEX name), the CUDA device number NVIDIA's EGL gives it
(EGL_NV_device_cuda) and its DRM file where there is one; then OpenGL's vendor, renderer and
version, and the device's UUID (GL_EXT_memory_object), which is the UUID nvidia-smi prints for
the card (GPU-xxxxxxxx-...). A query that the driver does not answer (Mesa has no CUDA device)
is None. Nothing here draws or changes state.
"""
import ctypes
import os

EGL_DEVICE_EXT = 0x322C
EGL_DRM_DEVICE_FILE_EXT = 0x3233
EGL_CUDA_DEVICE_NV = 0x323A
EGL_VENDOR = 0x3053
GL_VENDOR, GL_RENDERER, GL_VERSION = 0x1F00, 0x1F01, 0x1F02
GL_NUM_DEVICE_UUIDS_EXT, GL_DEVICE_UUID_EXT = 0x9596, 0x9597


def _egl():
    mode = getattr(os, 'RTLD_NOLOAD', 0) | getattr(os, 'RTLD_LAZY', 1)
    try:
        return ctypes.CDLL('libEGL.so.1', mode=mode)
    except OSError:
        return ctypes.CDLL('libEGL.so.1')


def _uuid(raw):
    h = bytes(raw).hex()
    return 'GPU-%s-%s-%s-%s-%s' % (h[:8], h[8:12], h[12:16], h[16:20], h[20:])


def describe(render_window):
    render_window.MakeCurrent()
    egl = _egl()
    egl.eglGetProcAddress.restype = ctypes.c_void_p
    egl.eglGetProcAddress.argtypes = [ctypes.c_char_p]
    egl.eglGetCurrentDisplay.restype = ctypes.c_void_p
    egl.eglQueryString.restype = ctypes.c_char_p
    egl.eglQueryString.argtypes = [ctypes.c_void_p, ctypes.c_int]

    def proc(name, restype, *argtypes):
        address = egl.eglGetProcAddress(name.encode())
        return ctypes.CFUNCTYPE(restype, *argtypes)(address) if address else None

    info = {'window': render_window.GetClassName(), 'egl_device_index': None,
            'egl_devices': None, 'cuda_device': None, 'drm_file': None, 'egl_vendor': None}
    display = egl.eglGetCurrentDisplay()
    if display:
        vendor = egl.eglQueryString(display, EGL_VENDOR)
        info['egl_vendor'] = vendor.decode() if vendor else None
        query_display = proc('eglQueryDisplayAttribEXT', ctypes.c_uint, ctypes.c_void_p,
                             ctypes.c_int, ctypes.POINTER(ctypes.c_ssize_t))
        query_devices = proc('eglQueryDevicesEXT', ctypes.c_uint, ctypes.c_int,
                             ctypes.POINTER(ctypes.c_void_p), ctypes.POINTER(ctypes.c_int))
        device_attrib = proc('eglQueryDeviceAttribEXT', ctypes.c_uint, ctypes.c_void_p,
                             ctypes.c_int, ctypes.POINTER(ctypes.c_ssize_t))
        device_string = proc('eglQueryDeviceStringEXT', ctypes.c_char_p, ctypes.c_void_p,
                             ctypes.c_int)
        device = ctypes.c_ssize_t(0)
        if query_display and query_display(display, EGL_DEVICE_EXT, ctypes.byref(device)):
            if query_devices:
                count = ctypes.c_int(0)
                devices = (ctypes.c_void_p * 32)()
                if query_devices(32, devices, ctypes.byref(count)):
                    listed = [devices[i] for i in range(count.value)]
                    info['egl_devices'] = count.value
                    if device.value in listed:
                        info['egl_device_index'] = listed.index(device.value)
            cuda = ctypes.c_ssize_t(-1)
            if device_attrib and device_attrib(ctypes.c_void_p(device.value), EGL_CUDA_DEVICE_NV,
                                               ctypes.byref(cuda)):
                info['cuda_device'] = cuda.value
            if device_string:
                drm = device_string(ctypes.c_void_p(device.value), EGL_DRM_DEVICE_FILE_EXT)
                info['drm_file'] = drm.decode() if drm else None
    get_string = proc('glGetString', ctypes.c_char_p, ctypes.c_uint)
    for key, name in (('gl_vendor', GL_VENDOR), ('gl_renderer', GL_RENDERER),
                      ('gl_version', GL_VERSION)):
        value = get_string(name) if get_string else None
        info[key] = value.decode() if value else None
    info['gpu_uuid'] = None
    get_integer = proc('glGetIntegerv', None, ctypes.c_uint, ctypes.POINTER(ctypes.c_int))
    get_uuid = proc('glGetUnsignedBytei_vEXT', None, ctypes.c_uint, ctypes.c_uint,
                    ctypes.POINTER(ctypes.c_ubyte))
    get_error = proc('glGetError', ctypes.c_uint)
    if get_integer and get_uuid and get_error:
        get_error()
        count = ctypes.c_int(0)
        get_integer(GL_NUM_DEVICE_UUIDS_EXT, ctypes.byref(count))
        if get_error() == 0 and count.value > 0:
            raw = (ctypes.c_ubyte * 16)()
            get_uuid(GL_DEVICE_UUID_EXT, 0, raw)
            if get_error() == 0:
                info['gpu_uuid'] = _uuid(raw)
    return info

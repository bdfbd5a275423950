# SPDX-FileCopyrightText: Copyright (c) 2026, the vtk-bloom authors
# SPDX-License-Identifier: BSD-3-Clause
"""Every property of the plugin's filters that changes the image does what its documentation says.

    scripts/pvbatch.sh ParaView/Testing/bloom_properties.py OUTDIR     (the ParaView half)
    compare(OUTDIR, vtkbloom, check)                                    (the VTK 9.1 half)

The ParaView half (pvbatch, one rank) writes small HDR test images (OUTDIR/*.vtk), lists the
properties of the Bloom, SeparableGaussian, BrightPass, PyramidDown and PyramidUp proxies
(ListProperties(): the Bloom proxy's include its BloomParameters sub-proxy's), and fails (exit
status 1) when one is neither in CASES nor in SKIPPED, so that a new XML property cannot go
untested. For every case it sets one property to a valid non-default value on a fresh proxy:
every other entry of an enumeration or string list, a flipped boolean, a value from the table
inside the property's range domain (checked against the domain here). Each case can name a
context (other properties set first, in both the baseline and the case) where the property
would otherwise legitimately change nothing. The outputs go to OUTDIR/outputs.npz and the cases
to OUTDIR/cases.json.

The VTK 9.1 half (run_tests.py, section 7, with the X11 build's `vtkbloom` package) configures
the matching vtkbloom filter through the C++ setters named in reference_setters() (not through
the XML: an enumeration entry's text is mapped to the C++ enum it documents), runs it on the
same images, and checks for each case that
  (1) the output differs from the baseline (the proxy with the context only) by more than
      CHANGED relative L2, or, where the documentation says the option does not change the
      result (exact work skipping, execution and convolution modes), stays within the
      documented bound; then, where the reference filter's own output moves, the proxy's is
      nearer the reference with the option than without it (the option reached the filter);
  (2) it equals the reference filter's output within SAME relative L2 (float rounding), with
      non-finite samples at the same places.
The baselines are checked against the reference as well, and each proxy's defaults against the
C++ getters of a new filter (but for KNOWN_DEFAULT_DIFFERENCES, which must still differ).
"""
import json
import os
import sys

# Relative L2 above which an output has changed, and below which two outputs are equal (float
# rounding; the plugin and the vtkbloom package compile the same code).
CHANGED = 1e-5
SAME = 1e-6

# The test images (OUTDIR/NAME.vtk), 160 x 120 unless said.
INPUTS = {
    'hdr': 'RGB float32 "rgb" (active) and "alt": a dim background, HDR blobs, a firefly, '
           'a ramp through the threshold',
    'nonfinite': 'hdr with a NaN, a +Inf and a -Inf sample',
    'coarse': '80 x 60 RGB float32, the coarse level for PyramidUp',
}

# Not tested, with the reason. Every other property ListProperties() returns must be in CASES.
SKIPPED = {
    'Bloom': {
        'Input': 'the data to filter, not an option (every case sets it)',
        'PresetInfo': 'information only (reads back the preset in use)',
    },
    'SeparableGaussian': {'Input': 'the data to filter'},
    'BrightPass': {'Input': 'the data to filter'},
    'PyramidDown': {'Input': 'the data to filter'},
    'PyramidUp': {
        'Input': 'the coarse level to filter',
        # Documented as optional, but vtkImagePyramidUp needs it to define its output (see
        # bloom_errors.py): every case connects it, and FineWeight's case tests what it adds.
        'Fine': 'the finer level, an input (connected in every case)',
    },
}

# Where a proxy's default (its XML default_values) is not the C++ default, although the XML says
# "Defaults are vtkBloomParameters'": each entry is checked to still differ (remove it once
# fixed), and the reference filters get the proxy's value, as ParaView pushes it at creation.
# (proxy, property) pairs whose XML default knowingly differs from the C++ one: none. (The
# XML's ClampLuminance said FLT_MAX where C++ has VTK_FLOAT_MAX, 1e38f, until this test.)
KNOWN_DEFAULT_DIFFERENCES = {}

# What each case sets. A property maps to one spec or a list of them; a spec may have:
#   values:  the values to set (for enumerations, string lists and booleans the default is every
#            other entry, or the flipped boolean);
#   context: properties set first, in the baseline too (enumerations by their text);
#   input:   the image for the Input port (default 'hdr'); PyramidUp's Fine is always 'hdr';
#   expect:  'change' (default), 'exact' (documented not to change the output: bit for bit),
#            or a float: documented to agree with the baseline within that relative L2.
_PSF = {'BloomMode': 'PSF'}
CASES = {
    'Bloom': {
        'Preset': {},
        'ExecutionMode': {'expect': 1e-5},  # "Both compute the same chain" (float32 rounding)
        'Scalars': {'values': [['POINTS', 'alt']]},
        'ThresholdMode': {},
        'Threshold': {'values': [2.0]},
        'Knee': {'values': [0.9]},
        'ClampLuminance': {'values': [2.0]},
        'StartLevel': {'values': [0]},
        'ReferenceHeight': {'values': [0, 240]},
        'NumberOfLevels': {'values': [3]},
        # Needs more levels than a 160-pixel image has: sizes in pixels, 12 levels.
        'LimitLevelsToImageSize': {'context': {'ReferenceHeight': 0, 'NumberOfLevels': 12}},
        'DownsampleKernel': {},
        'KarisAverage': {},
        'BlurKernel': {},
        'BlurStandardDeviation': {'values': [2.5]},
        'BlurRadius': {'values': [1]},
        'BlurGaussianKind': {},
        # The custom kernel is used only with BlurKernel Custom.
        'BlurHalfKernel': {'values': [[0.4, 0.2, 0.1]], 'context': {'BlurKernel': 'Custom'}},
        'BlurTapSpacing': {'values': [2.0]},
        'BlurIterations': {'values': [3, 0]},
        'UpsampleKernel': {},
        'AccumulateMode': {},
        'LevelWeights': {'values': [[1.0, 0.5, 0.25, 2.0]]},
        'CompositeMode': {},
        'Strength': {'values': [0.5, 0.0]},
        'Tint': {'values': [[1.0, 0.5, 0.25]]},
        'BloomMode': {},
        # The PSF parameters act in PSF mode only.
        'PSFType': {'context': _PSF},
        'AiryRadius': {'values': [5.0], 'context': _PSF},
        'Wavelengths': {'values': [[700.0, 550.0, 400.0]], 'context': _PSF},
        'PSFRadius': {'values': [6], 'context': _PSF},
        'PSFBorderMode': {'context': _PSF},
        'PSFTailScale': {'context': _PSF},
        # The core radius matters only with the tail on a coarser grid.
        'PSFCoreRadius': {'values': [6], 'context': dict(_PSF, PSFTailScale='Tail at 1/2')},
        # "How wide blurs are applied": the FFT agrees with direct taps to about 1e-7 (tested
        # to 1e-6). A wide blur in pixels, so that the choice matters.
        'ConvolutionMode': {'expect': 1e-6,
                            'context': {'ReferenceHeight': 0, 'BlurStandardDeviation': 12.0}},
        'SanitizeNonFinite': [
            {'input': 'nonfinite'},
            {'expect': 'exact'},  # "Finite input gives the same output bit for bit either way."
        ],
        # "Skip the chain, exactly, when nothing passes the bright pass": make nothing pass.
        'SkipEmptyBloom': {'expect': 'exact', 'context': {'Threshold': 1000.0}},
        # "Work only where the bloom can reach, exactly": the input's bright parts are local.
        'RestrictToBrightRegion': {'expect': 'exact'},
    },
    'SeparableGaussian': {
        'StandardDeviations': {'values': [[3.0, 1.0, 0.0]]},
        'Radius': {'values': [[2, 3, -1]]},
        'RadiusFactor': {'values': [1.0]},
        'KernelType': {},
        'BorderMode': {},
        'Method': {},
        # Exact method: direct taps or the FFT, which agree to about 1e-7 (tested to 1e-6).
        'ConvolutionMode': {'expect': 1e-6, 'context': {'StandardDeviations': [12.0, 12.0, 0.0]}},
        'SanitizeNonFinite': [{'input': 'nonfinite'}, {'expect': 'exact'}],
    },
    'BrightPass': {
        'Mode': {},
        'Threshold': {'values': [2.0]},
        'Knee': {'values': [0.1]},
        'ClampLuminance': {'values': [2.0]},
    },
    'PyramidDown': {
        'Kernel': {},
        'KarisAverage': {},
    },
    'PyramidUp': {
        'Kernel': {'input': 'coarse'},
        'CoarseWeight': {'values': [0.5], 'input': 'coarse'},
        'FineWeight': {'values': [0.5], 'input': 'coarse'},
    },
}


def specs(proxy_name, prop):
    spec = CASES[proxy_name][prop]
    return spec if isinstance(spec, list) else [spec]


# ------------------------------------------------------------------------------------------------
# The test images (numpy only: written by the ParaView half, read by both).

def make_images(np):
    ny, nx = 120, 160
    y, x = np.mgrid[0:ny, 0:nx].astype(np.float64)

    def blob(cx, cy, sigma, rgb):
        g = np.exp(-((x - cx) ** 2 + (y - cy) ** 2) / (2.0 * sigma ** 2))
        return g[..., None] * np.asarray(rgb, dtype=np.float64)

    background = (0.05 + 0.45 * (x / nx) * (0.5 + 0.5 * y / ny))[..., None] * \
        np.array([1.0, 0.9, 0.7])
    rgb = background + blob(40, 30, 4, [6.0, 3.0, 1.0]) + blob(110, 80, 6, [1.2, 1.5, 2.5]) + \
        blob(132, 24, 2, [3.0, 8.0, 3.0])
    # A ramp of luminance 0.6 .. 1.8 through the threshold and its knee.
    rgb[100:108, 20:100] += np.linspace(0.6, 1.8, 80)[None, :, None] - background[100:108, 20:100]
    rgb[90, 70] = [60.0, 50.0, 40.0]  # a firefly
    alt = background[:, ::-1] + blob(80, 60, 8, [4.0, 1.0, 6.0])
    bad = rgb.copy()
    bad[20, 100] = np.nan
    bad[60, 5, 1] = np.inf
    bad[110, 140, 0] = -np.inf
    cy, cx = np.mgrid[0:60, 0:80].astype(np.float64)
    coarse = (0.2 + np.exp(-((cx - 30) ** 2 + (cy - 20) ** 2) / 18.0) * 5.0)[..., None] * \
        np.array([1.0, 0.6, 0.3]) + (cx / 80.0)[..., None]
    return {'hdr': {'rgb': rgb, 'alt': alt}, 'nonfinite': {'rgb': bad},
            'coarse': {'rgb': coarse}}


def write_images(out):
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOLegacy import vtkStructuredPointsWriter

    for name, arrays in make_images(np).items():
        image = vtkImageData()
        ny, nx, _ = arrays['rgb'].shape
        image.SetDimensions(nx, ny, 1)
        for i, (array_name, values) in enumerate(arrays.items()):
            array = numpy_to_vtk(np.ascontiguousarray(values.reshape(-1, 3), dtype=np.float32),
                                 deep=True)
            array.SetName(array_name)
            if i == 0:
                image.GetPointData().SetScalars(array)
            else:
                image.GetPointData().AddArray(array)
        # Legacy binary: exact floats, and no cached array ranges, which the XML writer
        # stores and its reader cannot parse back when they are NaN.
        writer = vtkStructuredPointsWriter()
        writer.SetFileName(os.path.join(out, name + '.vtk'))
        writer.SetInputData(image)
        writer.SetFileTypeToBinary()
        if not writer.Write():
            raise RuntimeError('cannot write ' + name)


# ------------------------------------------------------------------------------------------------
# The ParaView half.

def domains(prop):
    """The property's server-manager domains, by class name."""
    found = {}
    iterator = prop.SMProperty.NewDomainIterator()
    iterator.Begin()
    while not iterator.IsAtEnd():
        domain = iterator.GetDomain()
        found[domain.GetClassName()] = domain
        iterator.Next()
    return found


def entries(domain):
    if domain.IsA('vtkSMEnumerationDomain'):
        return [domain.GetEntryText(i) for i in range(domain.GetNumberOfEntries())]
    return [domain.GetString(i) for i in range(domain.GetNumberOfStrings())]


def in_range(domain, values):
    """Whether every element is inside the range domain (a one-value domain bounds them all)."""
    for i, value in enumerate(values):
        k = i if domain.GetMinimumExists(i) or domain.GetMaximumExists(i) else 0
        if domain.GetMinimumExists(k) and value < domain.GetMinimum(k):
            return False
        if domain.GetMaximumExists(k) and value > domain.GetMaximum(k):
            return False
    return True


def plain(value):
    """A property's value as JSON: a number, a string or a list of them."""
    if value is None or isinstance(value, (str, int, float)):
        return value
    values = [plain(v) for v in value]
    return values[0] if len(values) == 1 else values


def paraview_half(out):
    import numpy as np
    import paraview.simple as pv
    from paraview import servermanager
    from vtkmodules.util.numpy_support import vtk_to_numpy

    os.makedirs(out, exist_ok=True)
    for stale in ('cases.json', 'outputs.npz'):
        if os.path.exists(os.path.join(out, stale)):
            os.remove(os.path.join(out, stale))
    write_images(out)
    readers = {name: pv.LegacyVTKReader(FileNames=[os.path.join(out, name + '.vtk')])
               for name in INPUTS}
    failures = []
    outputs = {}
    cases = []
    baselines = {}
    all_defaults = {}

    def fail(message):
        print('bloom_properties: FAIL ' + message, flush=True)
        failures.append(message)

    def create(proxy_name, input_name):
        inputs = {'Input': readers[input_name]}
        if proxy_name == 'PyramidUp':
            inputs['Fine'] = readers['hdr']
        return getattr(pv, proxy_name)(**inputs)

    def make(proxy_name, input_name, context):
        proxy = create(proxy_name, input_name)
        for prop, value in context.items():
            setattr(proxy, prop, value)
        return proxy

    def run(proxy):
        proxy.UpdatePipeline()
        image = servermanager.Fetch(proxy)
        scalars = image.GetPointData().GetScalars()
        nx, ny, nz = image.GetDimensions()
        values = vtk_to_numpy(scalars).reshape(nz, ny, nx, -1).copy()
        pv.Delete(proxy)
        return values

    for proxy_name, table in CASES.items():
        probe = create(proxy_name, 'hdr')
        listed = list(probe.ListProperties())
        skipped = SKIPPED.get(proxy_name, {})
        for prop in listed:
            if prop not in table and prop not in skipped:
                fail('%s.%s is neither tested (CASES) nor skipped (SKIPPED)' % (proxy_name, prop))
        for prop in list(table) + list(skipped):
            if prop not in listed:
                fail('%s.%s is in the tables but not a property of the proxy' % (proxy_name, prop))
        defaults = {prop: plain(getattr(probe, prop)) for prop in table if prop in listed}
        all_defaults[proxy_name] = defaults
        pv.Delete(probe)

        for prop in table:
            if prop not in listed:
                continue
            for spec in specs(proxy_name, prop):
                context = spec.get('context', {})
                input_name = spec.get('input', 'hdr')
                probe = make(proxy_name, input_name, context)
                handle = probe.GetProperty(prop)
                default = plain(getattr(probe, prop))
                found = domains(handle)
                choices = None
                for kind in ('vtkSMEnumerationDomain', 'vtkSMStringListDomain'):
                    if kind in found:
                        choices = entries(found[kind])
                if 'vtkSMBooleanDomain' in found:
                    choices = [0, 1]
                values = spec.get('values')
                if values is None:
                    if choices is None:
                        fail('%s.%s: no values given and no enumeration or boolean domain'
                             % (proxy_name, prop))
                        values = []
                    else:
                        current = default[0] if isinstance(default, list) and \
                            len(default) == 1 else default
                        values = [c for c in choices if c != current]
                pv.Delete(probe)
                key = json.dumps([proxy_name, input_name, context], sort_keys=True)
                if key not in baselines:
                    baselines[key] = 'base-%d' % len(baselines)
                    outputs[baselines[key]] = run(make(proxy_name, input_name, context))
                for value in values:
                    as_list = value if isinstance(value, list) else [value]
                    if choices is not None and value not in choices:
                        fail('%s.%s = %r: not in its domain %r'
                             % (proxy_name, prop, value, choices))
                    for kind in ('vtkSMDoubleRangeDomain', 'vtkSMIntRangeDomain'):
                        if kind in found and not in_range(found[kind], as_list):
                            fail('%s.%s = %r: outside its range' % (proxy_name, prop, value))
                    if value == default or as_list == default:
                        fail('%s.%s = %r is its default' % (proxy_name, prop, value))
                    proxy = make(proxy_name, input_name, context)
                    setattr(proxy, prop, value)
                    name = 'case-%d' % len(cases)
                    outputs[name] = run(proxy)
                    cases.append({'name': name, 'proxy': proxy_name, 'property': prop,
                                  'value': value, 'default': defaults.get(prop),
                                  'context': context, 'input': input_name,
                                  'expect': spec.get('expect', 'change'),
                                  'baseline': baselines[key]})
    np.savez(os.path.join(out, 'outputs.npz'), **outputs)
    with open(os.path.join(out, 'cases.json'), 'w') as f:
        json.dump({'cases': cases, 'defaults': all_defaults, 'failures': failures,
                   'baselines': {v: json.loads(k) for k, v in baselines.items()}}, f, indent=1)
    print('bloom_properties: %d cases, %d baselines, %d failure(s)'
          % (len(cases), len(baselines), len(failures)), flush=True)
    return 1 if failures else 0


# ------------------------------------------------------------------------------------------------
# The VTK 9.1 half: the reference configuration of each property, through the C++ setters.

class Setting:
    """One property on the reference filter: `target` 'parameters' (the filter's
    vtkBloomParameters) or 'filter', through Set<name> and Get<name>. `enum` maps an
    enumeration entry's text to the C++ enum its documentation names; `expand` passes a vector
    as separate arguments."""

    def __init__(self, target, name, enum=None, expand=False):
        self.target, self.name, self.enum, self.expand = target, name, enum, expand

    def _object(self, f):
        return f.GetParameters() if self.target == 'parameters' else f

    def set(self, f, state, value):
        value = self.enum[value] if self.enum is not None else value
        method = getattr(self._object(f), 'Set' + self.name)
        method(*value) if self.expand else method(value)

    def default(self, f):
        """The C++ default, as the proxy would show it."""
        value = getattr(self._object(f), 'Get' + self.name)()
        if isinstance(value, (tuple, list)):
            value = list(value)
            return value[0] if len(value) == 1 else value
        if self.enum is not None:
            return {v: k for k, v in self.enum.items()}.get(value, value)
        return int(value) if isinstance(value, bool) else value


class Special:
    """A property the reference sets its own way, with no C++ default to compare."""

    def __init__(self, apply):
        self.set = apply

    def default(self, f):
        return None


def reference_setters(vtkbloom):
    """proxy -> property -> Setting (or Special)."""
    B = vtkbloom.vtkBloomParameters
    T = vtkbloom.vtkImageBloomThreshold
    G = vtkbloom.vtkImageSeparableGaussian
    D = vtkbloom.vtkImagePyramidDown
    U = vtkbloom.vtkImagePyramidUp
    I = vtkbloom.vtkImageBloom  # noqa: E741

    def param(name, enum=None, expand=False):
        return Setting('parameters', name, enum, expand)

    def own(name, enum=None, expand=False):
        return Setting('filter', name, enum, expand)

    def scalars(f, state, value):
        state['scalars'] = value[1]

    thresholds = {'Excess knee': T.EXCESS_KNEE, 'Smoothstep knee': T.SMOOTHSTEP_KNEE,
                  'Quadratic knee': T.QUADRATIC_KNEE, 'Hard luminance': T.HARD_LUMINANCE,
                  'Per channel': T.PER_CHANNEL, 'None': T.NONE}
    down = {'Jimenez 13-tap': D.JIMENEZ13, 'Box': D.BOX, 'Binomial': D.BINOMIAL}
    gaussian_kinds = {'Sampled': G.SAMPLED, 'Integrated': G.INTEGRATED, 'Discrete': G.DISCRETE}
    convolution = {'Automatic': B.CONVOLUTION_AUTOMATIC, 'Direct': B.CONVOLUTION_DIRECT,
                   'FFT': B.CONVOLUTION_FFT}
    return {
        'Bloom': {
            # vtkPVImageBloom's own property ("custom" or a preset of vtkBloomParameters).
            'Preset': Special(lambda f, state, value: f.GetParameters().SetPreset(value)),
            'ExecutionMode': own('ExecutionMode', {'Fast': I.FAST, 'Reference': I.REFERENCE}),
            'Scalars': Special(scalars),
            'ThresholdMode': param('ThresholdMode', thresholds),
            'Threshold': param('Threshold'),
            'Knee': param('Knee'),
            'ClampLuminance': param('ClampLuminance'),
            'StartLevel': param('StartLevel'),
            'ReferenceHeight': param('ReferenceHeight'),
            'NumberOfLevels': param('NumberOfLevels'),
            'LimitLevelsToImageSize': param('LimitLevelsToImageSize'),
            'DownsampleKernel': param('DownsampleKernel', down),
            'KarisAverage': param('KarisAverage'),
            'BlurKernel': param('BlurKernel', {'Gaussian': B.BLUR_GAUSSIAN,
                                                  'Custom': B.BLUR_CUSTOM}),
            'BlurStandardDeviation': param('BlurStandardDeviation'),
            'BlurRadius': param('BlurRadius'),
            'BlurGaussianKind': param('BlurGaussianKind', gaussian_kinds),
            'BlurHalfKernel': param('BlurHalfKernel'),
            'BlurTapSpacing': param('BlurTapSpacing'),
            'BlurIterations': param('BlurIterations'),
            'UpsampleKernel': param('UpsampleKernel', {'Tent': U.TENT, 'Bilinear': U.BILINEAR}),
            'AccumulateMode': param('AccumulateMode', {'Cascade': B.CASCADE,
                                                          'Direct': B.DIRECT}),
            'LevelWeights': param('LevelWeights'),
            'CompositeMode': param('CompositeMode', {'Additive': B.ADDITIVE, 'Lerp': B.LERP}),
            'Strength': param('Strength'),
            'Tint': param('Tint', expand=True),
            'BloomMode': param('BloomMode', {'Pyramid': B.BLOOM_PYRAMID, 'PSF': B.BLOOM_PSF}),
            'PSFType': param('PSFType', {'Airy': B.PSF_AIRY, 'Gaussians': B.PSF_GAUSSIANS}),
            'AiryRadius': param('AiryRadius'),
            'Wavelengths': param('Wavelengths', expand=True),
            'PSFRadius': param('PSFRadius'),
            # vtkBloomParameters' PSF borders are the linear operators' (1 reflect, 2 zero),
            # numbered as vtkImageSeparableGaussian's.
            'PSFBorderMode': param('PSFBorderMode', {'Reflect (conserves energy)': G.REFLECT,
                                                        'Zero': G.ZERO}),
            'PSFTailScale': param('PSFTailScale', {'Exact': 1, 'Tail at 1/2': 2,
                                                      'Tail at 1/4': 4, 'Tail at 1/8': 8}),
            'PSFCoreRadius': param('PSFCoreRadius'),
            'ConvolutionMode': param('ConvolutionMode', convolution),
            'SanitizeNonFinite': param('SanitizeNonFinite'),
            'SkipEmptyBloom': param('SkipEmptyBloom'),
            'RestrictToBrightRegion': param('RestrictToBrightRegion'),
        },
        'SeparableGaussian': {
            'StandardDeviations': own('StandardDeviations', expand=True),
            'Radius': own('Radius', expand=True),
            'RadiusFactor': own('RadiusFactor'),
            'KernelType': own('KernelType', gaussian_kinds),
            'BorderMode': own('BorderMode', {'Clamp': G.CLAMP, 'Reflect': G.REFLECT,
                                                'Zero': G.ZERO}),
            'Method': own('Method', {'Exact': G.EXACT, 'Box cascade (3)': G.BOX_CASCADE_3,
                                        'Box cascade (5)': G.BOX_CASCADE_5,
                                        'Recursive': G.RECURSIVE}),
            'ConvolutionMode': own('ConvolutionMode', convolution),
            'SanitizeNonFinite': own('SanitizeNonFinite'),
        },
        'BrightPass': {
            'Mode': own('Mode', thresholds),
            'Threshold': own('Threshold'),
            'Knee': own('Knee'),
            'ClampLuminance': own('ClampLuminance'),
        },
        'PyramidDown': {
            'Kernel': own('Kernel', down),
            'KarisAverage': own('KarisAverage'),
        },
        'PyramidUp': {
            'Kernel': own('Kernel', {'Tent': U.TENT, 'Bilinear': U.BILINEAR}),
            'CoarseWeight': own('CoarseWeight'),
            'FineWeight': own('FineWeight'),
        },
    }


REFERENCE_CLASSES = {'Bloom': 'vtkImageBloom', 'SeparableGaussian': 'vtkImageSeparableGaussian',
                     'BrightPass': 'vtkImageBloomThreshold', 'PyramidDown': 'vtkImagePyramidDown',
                     'PyramidUp': 'vtkImagePyramidUp'}


def compare(out, vtkbloom, check):
    """Check every case of OUTDIR/cases.json against the vtkbloom filters; report through
    check(ok, message)."""
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOLegacy import vtkStructuredPointsReader

    with open(os.path.join(out, 'cases.json')) as f:
        manifest = json.load(f)
    outputs = np.load(os.path.join(out, 'outputs.npz'))
    setters = reference_setters(vtkbloom)
    images = {}

    def image(name, scalars=None):
        if (name, scalars) not in images:
            reader = vtkStructuredPointsReader()
            reader.SetFileName(os.path.join(out, name + '.vtk'))
            reader.Update()
            data = reader.GetOutput()
            if scalars is not None:
                data.GetPointData().SetActiveScalars(scalars)
            images[(name, scalars)] = data
        return images[(name, scalars)]

    def reference(proxy_name, input_name, settings):
        """The vtkbloom filter's output with `settings` ((property, value) pairs) applied."""
        f = getattr(vtkbloom, REFERENCE_CLASSES[proxy_name])()
        state = {}
        for (proxy, prop) in KNOWN_DEFAULT_DIFFERENCES:
            if proxy == proxy_name:
                setters[proxy][prop].set(f, state, manifest['defaults'][proxy][prop])
        for prop, value in settings:
            setters[proxy_name][prop].set(f, state, value)
        f.SetInputData(image(input_name, state.get('scalars')))
        if proxy_name == 'PyramidUp':
            f.SetInputData(1, image('hdr'))
        f.Update()
        result = f.GetOutput()
        nx, ny, nz = result.GetDimensions()
        return vtk_to_numpy(result.GetPointData().GetScalars()).reshape(nz, ny, nx, -1).copy()

    def distance(a, b):
        """Relative L2 of a against b over their finite samples; inf when their shapes or
        their non-finite samples differ."""
        if a.shape != b.shape:
            return float('inf')
        a, b = a.astype(np.float64), b.astype(np.float64)
        finite = np.isfinite(a)
        if not np.array_equal(finite, np.isfinite(b)) or \
                not np.array_equal(np.where(finite, 0, a), np.where(finite, 0, b), equal_nan=True):
            return float('inf')
        return float(np.linalg.norm(a[finite] - b[finite]) / max(np.linalg.norm(b[finite]), 1e-300))

    def identical(a, b):
        return a.shape == b.shape and np.array_equal(a, b, equal_nan=True)

    for failure in manifest['failures']:
        check(False, 'properties: ' + failure)

    def same_value(a, b):
        if isinstance(a, list) or isinstance(b, list):
            a, b = (v if isinstance(v, list) else [v] for v in (a, b))
            return len(a) == len(b) and all(same_value(x, y) for x, y in zip(a, b))
        if isinstance(a, (int, float)) and isinstance(b, (int, float)):
            return abs(a - b) <= 1e-12 * max(abs(a), abs(b))
        return a == b

    # The proxies' defaults against the C++ defaults.
    for proxy_name, defaults in manifest['defaults'].items():
        fresh = getattr(vtkbloom, REFERENCE_CLASSES[proxy_name])()
        agree, differ = [], []
        for prop, value in sorted(defaults.items()):
            expected = setters[proxy_name][prop].default(fresh)
            if expected is None:
                continue
            known = KNOWN_DEFAULT_DIFFERENCES.get((proxy_name, prop))
            if known:
                check(not same_value(value, expected), 'properties: %s.%s default %r, C++ %r: '
                      'known difference (%s)%s' % (proxy_name, prop, value, expected, known,
                      '' if not same_value(value, expected) else ' is gone: remove it from '
                      'KNOWN_DEFAULT_DIFFERENCES'))
            elif same_value(value, expected):
                agree.append(prop)
            else:
                differ.append('%s %r (C++ %r)' % (prop, value, expected))
        check(not differ, 'properties: %s defaults equal the C++ defaults (%d)%s' % (
            proxy_name, len(agree), ''.join('; differs: ' + d for d in differ)))
    references = {}
    for name, (proxy_name, input_name, context) in manifest['baselines'].items():
        try:
            references[name] = reference(proxy_name, input_name, sorted(context.items()))
        except KeyError as error:
            check(False, 'properties: %s baseline %s: no reference for %s'
                  % (proxy_name, context, error))
            continue
        error = distance(outputs[name], references[name])
        check(error <= SAME, 'properties: %s %s on %s equals vtkbloom: %.1e'
              % (proxy_name, context or 'at its defaults', input_name, error))
    for case in manifest['cases']:
        proxy_name, prop, value = case['proxy'], case['property'], case['value']
        what = '%s.%s = %s (default %s%s)' % (
            proxy_name, prop, json.dumps(value), json.dumps(case['default']),
            ', with %s' % json.dumps(case['context']) if case['context'] else '')
        if case['input'] != 'hdr':
            what += ' on ' + case['input']
        got, base = outputs[case['name']], outputs[case['baseline']]
        try:
            expected = reference(proxy_name, case['input'],
                                 sorted(case['context'].items()) + [(prop, value)])
        except KeyError as error:
            check(False, 'properties: %s: no reference setting for %s' % (what, error))
            continue
        moved = distance(got, base)
        error = distance(got, expected)
        expect = case['expect']
        if expect == 'change':
            ok = moved > CHANGED and error <= SAME
            claim = 'changes the output by %.1e (> %g)' % (moved, CHANGED)
        elif expect == 'exact':
            ok = identical(got, base) and error <= SAME
            claim = 'leaves the output bit for bit (%s)' % ('yes' if identical(got, base) else
                                                           'no: %.1e' % moved)
        else:
            ok = moved <= expect and error <= SAME
            claim = 'keeps the output within %g: %.1e' % (expect, moved)
        # Where the reference moves with the option, the option must have reached the filter:
        # the output is nearer the reference with it than the one without it.
        base_reference = references.get(case['baseline'])
        if base_reference is not None and not identical(expected, base_reference):
            nearer = distance(got, expected) < distance(got, base_reference)
            ok = ok and nearer
            claim += ', nearer vtkbloom with it than without (%s)' % ('yes' if nearer else 'no')
        elif expect != 'change':
            claim += ', not visible in vtkbloom\'s output either'
        check(ok, 'properties: %s %s, equals vtkbloom with the same setting: %.1e'
              % (what, claim, error))
    print('properties: %d cases of %d properties' % (
        len(manifest['cases']), len({(c['proxy'], c['property']) for c in manifest['cases']})))


if __name__ == '__main__':
    sys.exit(paraview_half(sys.argv[1]))

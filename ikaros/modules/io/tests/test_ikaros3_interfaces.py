"""The IO, sound and device classes accept every input, output and parameter of Ikaros 3's
current class files, with Ikaros 3's defaults in a file of dialect 3. The interface below is
transcribed from reference/IKAROS3-INTERFACES.md (names and defaults only). The few defaults
this project states otherwise are listed, with the reason, in DIFFERENT_DEFAULTS."""
import importlib
import pkgutil

import pytest


INTERFACES = {
    "ADSREnvelope": (["GATE", "TRIG"], ["OUTPUT"], {"sample_rate": "0", "attack": "0.01", "decay": "0.1", "sustain": "0.7", "release": "0.2"}),
    "AmbientLight": ([], ["OUTPUT"], {"method": "DSR", "use_system_time": "fals", "year": "2024", "month": "1", "day": "1", "time": "0", "radiation": "1", "longitude": "55.577918", "latitude": "12.814571"}),
    "AudioDelay": (["INPUT"], ["OUTPUT"], {"sample_rate": "0", "delay_time": "0.25", "feedback_gain": "0.35", "mix": "0.5", "lowpass_cutoff": "4000"}),
    "AudioFilter": (["INPUT", "CUTOFF", "CUTOFF_MOD", "RESONANCE_MOD"], ["OUTPUT"], {"sample_rate": "0", "cutoff": "200", "resonance": "0", "envelope_amount": "4"}),
    "AudioInput": ([], ["OUTPUT"], {"samplingrate": "44100", "buffersize": "4096"}),
    "AudioOscillator": (["INPUT", "MODULATION"], ["OUTPUT"], {"wave_shape": "sine", "frequency": "440", "sample_rate": "0", "detune": "0", "multiplier": "1", "volume": "1", "modulation_gain": "1", "duty_cycle": "0.5"}),
    "AudioOutput": (["INPUT"], [], {"sample_rate": "44100", "buffer_size": "@sample_rate*@tick_duration"}),
    "AudioReverb": (["INPUT"], ["OUTPUT"], {"sample_rate": "0", "mix": "0.25", "decay": "0.7", "damping": "0.4", "pre_delay": "0.03"}),
    "AudioSynth": (["WAVESHAPE", "FREQUENCY", "AMPLITUDE", "TRIGGER"], ["OUTPUT"], {"sample_rate": "22050"}),
    "EpiSpeech": (["TRIG", "INHIBITION", "ATTRIBUTE1", "ATTRIBUTE2"], ["PLAYING", "COMPLETED", "ACTIVE", "RMS", "VOLUME"], {"voice": "Noelle (Enhanced)", "text": "hello there,yes,no", "scale_volume": "1.0", "lag": "100.0"}),
    "EpiVoice": (["TRIG", "INTENSITY", "INHIBITION"], ["PLAYING", "COMPLETED", "ACTIVE", "RMS", "VOLUME"], {"sounds": "", "scale_volume": "1.0", "lag": "100.0", "intentities": "3", "variants": "5"}),
    "InputAudioFile": ([], ["OUTPUT"], {"filename": "inputaudio.wav", "buffer_size": "4096", "channels": "1", "repeat": "true"}),
    "InputFile": ([], [], {"filename": None, "format": "auto", "delimiter": "", "header": "true", "send_end_of_file": "true"}),
    "InputImage": ([], ["INTENSITY", "OUTPUT"], {"filename": None, "filecount": "1", "iterations": "0", "read_once": "yes", "size_x": "640", "size_y": "480"}),
    "InputVideo": ([], ["RED", "GREEN", "BLUE", "INTENSITY", "OUTPUT"], {"size_x": "1280", "size_y": "720", "list_devices": "no", "frame_rate": "30", "id": "0", "device_name": "", "device_index": "0"}),
    "InputVideoFile": ([], ["RED", "GREEN", "BLUE", "INTENSITY", "OUTPUT", "RESTART"], {"filename": None, "size_x": "0", "size_y": "0", "loop": "no", "info": "no"}),
    "InputVideoStream": ([], ["RED", "GREEN", "BLUE", "INTENSITY", "OUTPUT"], {"size_x": "1280", "size_y": "720", "url": "", "info": "false", "synchronized_framegrabber": "false", "synchronized_tick": "true", "uv4l": "false"}),
    "LaunchpadAnimation": (["KEY", "TRIG", "EVENT_COUNT"], ["COLOR"], {"speed": "1", "brightness": "1", "saturation": "0.9", "sparkle": "0.65", "reactivity": "1", "frame_rate": "30"}),
    "LaunchpadLED": (["COLOR", "PLAYING"], ["CONNECTED", "DESTINATION_COUNT", "LAST_UPDATE_COUNT"], {"destination_name": "LPX MIDI In", "layout_width": "8", "idle_brightness": "0.2", "playing_brightness": "1", "programmer_mode": "true", "clear_on_stop": "true", "restore_live_mode": "true"}),
    "MidiInput": ([], ["KEY", "GATE", "TRIG", "EVENT_COUNT", "SOURCE_COUNT", "CONNECTED", "LAST_BATCH_COUNT"], {"source_name": "", "source_index": "-1", "trig_hold_ticks": "1"}),
    "OutputAudioFile": (["INPUT"], [], {"filename": "output.wav", "sample_rate": "0", "bits_per_sample": "16"}),
    "OutputFile": (["INPUT", "WRITE", "NEWFILE"], [], {"filename": "output.csv", "format": "csv", "delimiter": "", "number_format": "fixed", "decimals": "4", "timestamp": "time", "existing_file": "error", "start_index": "0", "flush_interval": "1", "header": "true", "single_trigger": "no", "directory": ""}),
    "OutputImage": (["INPUT", "WRITE"], [], {"directory": "", "filename": "output.jpg", "quality": "90", "start_index": "0", "single_trigger": "no"}),
    "SoundOutput": (["TRIG", "INHIBITION"], ["PLAYING", "COMPLETED", "ACTIVE", "RMS", "VOLUME"], {"sounds": "", "scale_volume": "1.0", "lag": "100.0"}),
    "UM7": ([], ["ROLL", "PITCH", "YAW", "ProcessedGyro", "ProcessedAccel", "EulerAngles"], {"port": "/dev/cu.usbserial-AU04OIL4"}),
}

# the options Ikaros 3 gives (each must be accepted)
OPTIONS = {
    ("AmbientLight", "method"): ["DSR", "OnOff"],
    ("AudioOscillator", "wave_shape"): ["sine", "square", "saw", "triangle", "ramp", "pulse"],
    ("InputFile", "format"): ["auto", "text", "csv", "tsv", "json", "jsonl"],
    ("OutputFile", "format"): ["csv", "tsv", "json", "jsonl"],
    ("OutputFile", "number_format"): ["fixed", "full"],
    ("OutputFile", "existing_file"): ["error", "overwrite", "append"],
}

# defaults stated otherwise here, and why (each class description says so too)
DIFFERENT_DEFAULTS = {
    ("AudioOutput", "buffer_size"): "0 plays all of INPUT, which is sample_rate × "
                                    "tick_duration samples when it comes from the audio classes",
    ("InputImage", "size_x"): "unset: the size of the first file (no image is resized "
                              "unless asked); TESTS.md row 289 reads a 3 × 4 image as 3 × 4",
    ("InputImage", "size_y"): "as size_x",
    ("InputVideoFile", "size_x"): "unset, as Ikaros 3's 0: the file's size",
    ("InputVideoFile", "size_y"): "as size_x",
}


def classes():
    found = {}
    for folder in ("io", "sound"):
        package = importlib.import_module(f"ikaros.modules.{folder}")
        for info in pkgutil.iter_modules(package.__path__):
            if info.name in INTERFACES:
                module = importlib.import_module(f"ikaros.modules.{folder}.{info.name}")
                found[info.name] = getattr(module, info.name)
    return found


CLASSES = classes()


def same(text: str, value, kind: str) -> bool:
    """Whether Ikaros 3's default text gives this project's default value."""
    if kind == "bool":
        return value is {"true": True, "yes": True, "false": False, "fals": False,
                         "no": False}[text]
    if kind in ("number", "int"):
        return value is not None and float(value) == float(text)
    return str(value) == text


def test_every_class_is_here():
    assert sorted(CLASSES) == sorted(INTERFACES)


@pytest.mark.parametrize("name", sorted(INTERFACES))
def test_ports_and_parameters_with_ikaros_3_defaults(name):
    inputs, outputs, parameters = INTERFACES[name]
    description = CLASSES[name].description
    assert set(inputs) <= {i.name for i in description.inputs}
    assert set(outputs) <= {o.name for o in description.outputs}
    specs = {p.name: p for p in description.parameters}
    assert set(parameters) <= set(specs)
    for parameter, text in parameters.items():
        spec = specs[parameter]
        default = spec.default_v3 if spec.default_v3 is not None else spec.default
        if text is None or (name, parameter) in DIFFERENT_DEFAULTS:
            continue
        assert same(text, default, spec.type), (parameter, text, default)


@pytest.mark.parametrize("name, parameter", sorted(OPTIONS))
def test_ikaros_3_options(name, parameter):
    spec = {p.name: p for p in CLASSES[name].description.parameters}[parameter]
    assert set(OPTIONS[name, parameter]) <= set(spec.options)

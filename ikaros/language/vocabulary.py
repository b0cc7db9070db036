"""The names only one version of the original Ikaros uses: signs of which version a
model file was written for (ikaros/language/dialect.py). Made by
scripts/dialect_vocabulary.py from the reference's catalogues; do not edit by hand.
"""

# classes that only Ikaros 3 has (with the test-only classes of its kernel tests)
IKAROS3_CLASSES = frozenset({
    "ADSREnvelope", "ALIKEDFeatureExtractor", "AmbientLight", "AppleVisionFaceDetector",
    "AsyncLifecycleTestModule", "AudioDelay", "AudioFilter", "AudioInput",
    "AudioOscillator", "AudioOutput", "AudioReverb", "AudioSynth",
    "BalkeniusReactiveControl", "CameraRectification", "Cerebellum", "Clip",
    "ComputeEngineTestModule", "Concentration", "ConductanceNeuronPopulation",
    "ConvolutionalVariationalAutoEncoder", "CurrentPositionMapping", "DeepNetwork",
    "DelayFlatWindowSink", "DelaySequenceSource", "DelayStackedWindowSink",
    "DelayVectorSource", "DelayWindowSink", "DlibFaceDetector", "DlibFaceRecognizer",
    "DynamicMatrixCopy", "DynamicMatrixSink", "DynamicMatrixSource", "DynamixelController",
    "EpiServos", "EpiSpeech", "EpiVoice", "Exp", "FaceClassifier", "FeaturePointBoxes",
    "FeatureRegionFilter", "FirstTickReporter", "ForceCheck", "HeadServos", "Idle",
    "ImageMatching", "InputAudioFile", "InputImage", "IntegrateAndFirePopulation",
    "Invert", "KernelSizeTestModule", "KernelSizedInputTestModule", "KernelTestModule",
    "LaunchpadAnimation", "LaunchpadLED", "LeakyIntegrator", "LightGlueFeatureMatcher",
    "MatrixFunctionTestModule", "Maximum", "Median", "MidiInput", "Minimum", "Negate",
    "Not", "Oscillator", "OutputAudioFile", "OutputImage", "PersistentStateTestModule",
    "PointsToSalience", "PositionSelection", "Print", "Protocol",
    "PyramidalLucasKanadeTracker", "PythonModule", "RatePopulation",
    "RegressionStatistics", "RingWorld", "RobustTransformEstimator", "SCN",
    "SalienceIntegrator", "ServoControlTuning", "ServosSimulation", "SpikeGenerator",
    "Square", "StartupStepReporter", "Statistics", "System", "TaskLifecycleTestModule",
    "TemplateFeatureBank", "TemplatePolygonTransform", "TemplateTrackingController",
    "TimeSeries", "UM7", "WilsonCowan", "World2D"
})

# classes that only Ikaros 2 has
IKAROS2_CLASSES = frozenset({
    "ActionCompetition", "ArrayToMatrix", "AttentionFocus", "AttentionWindow",
    "Autoassociator", "BackProp", "BlackBox", "BlockMatching", "CIFaceDetector", "CSOM",
    "CSOM_L", "CSOM_PCA", "CalibrateCameraPosition", "ChangeDetector", "CircleDetector",
    "CoarseCoder", "ColorClassifier", "Concat", "Counter", "DFaceDetector", "DTracker",
    "DataBuffer", "DataConverter", "DecomposeTransform", "Delay", "DelayOne",
    "DepthBlobList", "DepthContourTrace", "DepthHistogram", "DepthPointList",
    "DepthSegmentation", "DepthTransform", "Dilate", "DirectionDetector", "Distance",
    "DoGFilter", "Dynamixel", "DynamixelConfigure", "EdgeSegmentation", "Epuck", "Erode",
    "EventTrigger", "Expression", "EyeModel", "FASTDetector", "FFT", "FanIn", "FanOut",
    "Flip", "Fuse", "GLRobotSimulator", "GaborFilter", "Gate", "GaussianEdgeDetector",
    "GaussianFilter", "GazeController", "GridWorld", "HarrisDetector", "Histogram",
    "HysteresisThresholding", "IPCClient", "IPCServer", "ImageConvolution", "InitialValue",
    "InputJPEG", "InputPNG", "InputRawImage", "InputSelector", "InputVideoAV",
    "IntegralImage", "IntervalCoder", "IntervalDecoder", "KNN", "KNN_Pick", "Kinect",
    "LearningModule", "LinearAssociator", "ListIterator", "LoGFilter", "LocalApproximator",
    "M02_Amygdala", "M02_Cortex", "M02_Hippocampus", "M02_OFC", "M02_SensoryCortex",
    "M02_Thalamus", "Map", "MarkerTracker", "MatrixRotation", "MatrixScale",
    "MatrixTranslation", "Maxima", "MazeGenerator", "Mean", "MedianFilter",
    "MemorySequencer", "MidiFilter", "MidiInterface", "MotionGuard", "MotionRecorder",
    "NetworkCamera", "NeuralArray", "NeuralField", "NucleusEnsemble", "Ones",
    "OscInterface", "OuterProduct", "OutputJPEG", "OutputPNG", "OutputRawImage",
    "OutputVideoFile", "Perception", "Perceptron", "Phidgets", "Polynomial",
    "PopulationCoder", "PopulationDecoder", "PrewittEdgeDetector", "QLearning", "RNN",
    "ReactionTimeStatistics", "RingBuffer", "RobertsEdgeDetector", "SSC32",
    "SaliencePoints", "SaliencyMap", "Select", "SelectMax", "SelectRow", "SetSubmatrix",
    "Sink", "SpatialClustering", "SpectralTiming", "Submatrix", "SumMatrix", "Summation",
    "Sweep", "Tanh", "TappedDelayLine", "TheEyeTribe", "TouchBoard", "TouchBoardGraph",
    "Trainer", "TruncateArray", "ValueAccumulator", "YARPPort", "ZeroCrossings"
})

# parameters that only Ikaros 3's class of that name has
IKAROS3_PARAMETERS = {
    "CannyEdgeDetector": frozenset({
        "high_threshold", "low_threshold", "sigma"
    }),
    "FadeCandy": frozenset({
        "simulate"
    }),
    "InputFile": frozenset({
        "delimiter", "format", "header"
    }),
    "InputVideo": frozenset({
        "device_index", "device_name"
    }),
    "InputVideoStream": frozenset({
        "synchronized_framegrabber", "synchronized_tick"
    }),
    "KalmanFilter": frozenset({
        "INITIAL_P", "INITIAL_STATE", "Q", "R", "innovation_gate", "input_size",
        "inversion_jitter"
    }),
    "Noise": frozenset({
        "max", "min", "seed", "stddev", "type"
    }),
    "Nucleus": frozenset({
        "activation_function", "burst_duration", "burst_level", "burst_time", "delta",
        "gamma", "output_offset", "output_scale", "refractory_period", "reset_level",
        "scale_inputs", "seed", "sigma", "theta", "time_constant"
    }),
    "OutputFile": frozenset({
        "delimiter", "existing_file", "flush_interval", "format", "header",
        "number_format", "single_trigger", "start_index"
    }),
    "PlanarArm": frozenset({
        "base_position", "circle_obstacle_count", "circle_obstacles",
        "finger_closed_angle", "finger_length", "finger_open_angle", "gripper_width",
        "initial_gripper", "initial_joint_angles", "joint_max", "joint_min",
        "line_obstacle_count", "line_obstacles", "link_lengths", "link_width",
        "max_joint_step", "movable_object", "palm_length", "solver_iterations",
        "world_height", "world_width"
    }),
    "Randomizer": frozenset({
        "seed", "size"
    }),
    "RotationConverter": frozenset({
        "size_x", "size_y"
    }),
    "SobelEdgeDetector": frozenset({
        "sigma"
    }),
    "SoundOutput": frozenset({
        "lag", "scale_volume"
    }),
    "StaufferGrimson": frozenset({
        "initial_variance", "learning_rate", "max_gaussians"
    }),
}

# option labels that only Ikaros 3's parameter of that name has
IKAROS3_LABELS = {
    "FunctionGenerator.type": frozenset({
        "sine"
    }),
    "RotationConverter.angle_unit": frozenset({
        "turns"
    }),
}

# inputs and outputs that only Ikaros 3's class of that name has
IKAROS3_PORTS = {
    "Arbiter": frozenset({
        "INPUT"
    }),
    "ArgMax": frozenset({
        "VALUE"
    }),
    "ColorMatch": frozenset({
        "INPUT", "TARGETINPUT"
    }),
    "ColorTransform": frozenset({
        "INPUT", "OUTPUT"
    }),
    "FadeCandy": frozenset({
        "LEFT_EYE", "MOUTH_HIGH", "MOUTH_LOW", "RIGHT_EYE"
    }),
    "InputVideo": frozenset({
        "OUTPUT"
    }),
    "InputVideoFile": frozenset({
        "OUTPUT"
    }),
    "InputVideoStream": frozenset({
        "OUTPUT"
    }),
    "KalmanFilter": frozenset({
        "GATED", "INPUT_VALID", "NORMALIZED_INNOVATION", "OBSERVATION_VALID", "RESET"
    }),
    "Max": frozenset({
        "INPUT"
    }),
    "Min": frozenset({
        "INPUT"
    }),
    "Nucleus": frozenset({
        "X"
    }),
    "OutputFile": frozenset({
        "INPUT"
    }),
    "PlanarArm": frozenset({
        "ARM_LINES", "BLOCKED", "ENCLOSED", "END_EFFECTOR", "GRIPPER", "GRIPPER_CONTACTS",
        "JOINT_ANGLES", "JOINT_COMMAND", "JOINT_POSITIONS", "LINK_CONTACTS",
        "MOVABLE_OBJECT", "OBJECTS", "OBJECT_CONTACTS", "RESET", "WALLS"
    }),
    "SequenceRecorder": frozenset({
        "ACTIVE", "CAN_PLAY", "COLOR", "ERROR", "LIMITING", "PLAYING", "SMOOTHING_START",
        "TARGET"
    }),
    "SoundOutput": frozenset({
        "ACTIVE", "COMPLETED", "INHIBITION", "PLAYING", "RMS", "TRIG", "VOLUME"
    }),
    "SpikingPopulation": frozenset({
        "EXCITATION", "EXCITATION_TOPOLOGY", "INHIBITION", "INTERNAL_TOPOLOGY"
    }),
    "StaufferGrimson": frozenset({
        "MEANS", "VARIANCES", "WEIGHTS"
    }),
    "WhiteBalance": frozenset({
        "INPUT", "OUTPUT"
    }),
}

# inputs and outputs that only Ikaros 2's class of that name has
IKAROS2_PORTS = {
    "Arbiter": frozenset({
        "INPUT_1", "INPUT_2", "INPUT_3", "VALUE_1", "VALUE_2", "VALUE_3"
    }),
    "CannyEdgeDetector": frozenset({
        "EDGES", "MAXIMA", "dGx", "dGy", "dx", "dy"
    }),
    "ColorMatch": frozenset({
        "INPUT0", "INPUT1", "INPUT2", "TARGETINPUT0", "TARGETINPUT1", "TARGETINPUT2"
    }),
    "ColorTransform": frozenset({
        "INPUT0", "INPUT1", "INPUT2", "OUTPUT0", "OUTPUT1", "OUTPUT2"
    }),
    "Max": frozenset({
        "INPUT1", "INPUT2"
    }),
    "Min": frozenset({
        "INPUT1", "INPUT2"
    }),
    "PlanarArm": frozenset({
        "ANGLES", "CONTACT", "DESIRED_ANGLES", "DISTANCE", "HAND_POSITION", "JOINTS",
        "TARGET"
    }),
    "SequenceRecorder": frozenset({
        "ENABLE", "KEYPOINTS", "LENGTHS", "MODE", "STATE", "TIME", "TIMESTAMPS", "TORQUE",
        "TRIG_OUT"
    }),
    "SoundOutput": frozenset({
        "INPUT"
    }),
    "SpikingPopulation": frozenset({
        "ADENOSINE", "EXCITATION_IN", "INHIBITION_IN"
    }),
    "WhiteBalance": frozenset({
        "INPUT0", "INPUT1", "INPUT2", "OUTPUT0", "OUTPUT1", "OUTPUT2"
    }),
}

"""ROS 2 message definitions (the ``.msg`` text with its dependencies, as rosbag2 writes
them into MCAP files as ``ros2msg`` schemas), for the messages ikaros records."""

SEPARATOR = "=" * 80

FLOAT32_MULTI_ARRAY = "\n".join([
    "MultiArrayLayout  layout",
    "float32[]         data",
    SEPARATOR,
    "MSG: std_msgs/MultiArrayLayout",
    "MultiArrayDimension[] dim",
    "uint32 data_offset",
    SEPARATOR,
    "MSG: std_msgs/MultiArrayDimension",
    "string label",
    "uint32 size",
    "uint32 stride",
]) + "\n"

DEFINITIONS = {"std_msgs/msg/Float32MultiArray": FLOAT32_MULTI_ARRAY}

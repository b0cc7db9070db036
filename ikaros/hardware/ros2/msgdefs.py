"""ROS 2 message definitions (the ``.msg`` text with its dependencies, as rosbag2 writes
them into MCAP files and Foxglove reads them as ``ros2msg`` schemas), for every message ikaros
publishes or records."""

SEPARATOR = "=" * 80


def _definition(own: list[str], *dependencies: tuple[str, list[str]]) -> str:
    lines = list(own)
    for name, fields in dependencies:
        lines += [SEPARATOR, f"MSG: {name}", *fields]
    return "\n".join(lines) + "\n"


_TIME = ("builtin_interfaces/Time", ["int32 sec", "uint32 nanosec"])
_HEADER = ("std_msgs/Header", ["builtin_interfaces/Time stamp", "string frame_id"])
_LAYOUT = ("std_msgs/MultiArrayLayout", ["MultiArrayDimension[] dim", "uint32 data_offset"])
_DIMENSION = ("std_msgs/MultiArrayDimension", ["string label", "uint32 size", "uint32 stride"])
_VECTOR3 = ("geometry_msgs/Vector3", ["float64 x", "float64 y", "float64 z"])

DEFINITIONS = {
    "std_msgs/msg/Float32": _definition(["float32 data"]),
    "std_msgs/msg/Float64": _definition(["float64 data"]),
    "std_msgs/msg/Float32MultiArray": _definition(
        ["MultiArrayLayout  layout", "float32[]         data"], _LAYOUT, _DIMENSION),
    "std_msgs/msg/Float64MultiArray": _definition(
        ["MultiArrayLayout  layout", "float64[]         data"], _LAYOUT, _DIMENSION),
    "geometry_msgs/msg/Twist": _definition(["Vector3  linear", "Vector3  angular"], _VECTOR3),
    "sensor_msgs/msg/JointState": _definition(
        ["std_msgs/Header header", "string[] name", "float64[] position",
         "float64[] velocity", "float64[] effort"], _HEADER, _TIME),
    "sensor_msgs/msg/Image": _definition(
        ["std_msgs/Header header", "uint32 height", "uint32 width", "string encoding",
         "uint8 is_bigendian", "uint32 step", "uint8[] data"], _HEADER, _TIME),
}

"""ROS 2 topics without a ROS installation: messages in ROS 2's CDR encoding (cdr.py,
messages.py), their definitions for recordings (msgdefs.py), and DDS through Eclipse Cyclone
DDS (dds.py, the optional extra ``ikaros[ros2]``) with the names and QoS a ROS 2 node uses."""

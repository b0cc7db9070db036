"""ROS 2 topics without a ROS installation: messages in ROS 2's CDR encoding (cdr.py,
messages.py), their definitions for recordings (msgdefs.py), and DDS through Eclipse Cyclone
DDS (dds.py, the optional extra ``ikaros[ros2]``) with the names and QoS a ROS 2 node uses."""

# Cyclone DDS settings (the CYCLONEDDS_URI environment variable) that keep DDS on this
# machine: the loopback interface, no multicast, peers found on 127.0.0.1. The tests and the
# example use them; a robot on the network needs Cyclone's defaults (or its own settings).
LOOPBACK = ("<CycloneDDS><Domain><General><Interfaces><NetworkInterface name=\"lo\"/>"
            "</Interfaces><AllowMulticast>false</AllowMulticast></General><Discovery>"
            "<ParticipantIndex>auto</ParticipantIndex><Peers><Peer address=\"127.0.0.1\"/>"
            "</Peers></Discovery></Domain></CycloneDDS>")

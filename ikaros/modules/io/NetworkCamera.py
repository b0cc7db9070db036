"""NetworkCamera: an IP camera's HTTP MJPEG stream (Axis style), grabbed in the background."""
from ikaros.module import Parameter

from ._camera import CameraInput, open_stream


class NetworkCamera(CameraInput):
    """Reads the MJPEG stream of a network camera at http://host_ip:host_port plus
    `image_request`, asking for `fps` frames per second and the JPEG `compression` (Axis
    cameras read these from the query). Frames are grabbed in a background thread and each
    tick publishes the newest; FRAME_AGE is its age and STALE is set when no frame came for
    `timeout` seconds (the stream is then opened again every second or so). Without size_x
    and size_y the outputs have the camera's frame size. An image_request that starts with
    rtsp:// or http:// is used as the whole address."""

    size_x = Parameter(None, "columns of the output frames; unset: the camera's", type="int")
    size_y = Parameter(None, "rows of the output frames; unset: the camera's", type="int")
    host_ip = Parameter("", "the camera's host name or IP address")
    host_port = Parameter(80, "the camera's HTTP port", type="int")
    image_request = Parameter("/axis-cgi/mjpg/video.cgi", "the path of the MJPEG stream on "
                              "the camera (the Axis streaming path by default)")
    fps = Parameter(10, "frames per second asked of the camera", type="int")
    compression = Parameter(50, "JPEG compression asked of the camera (0..100)", type="int")

    def stream_url(self) -> str:
        if "://" in self.image_request:
            return self.image_request
        path = self.image_request if self.image_request.startswith("/") \
            else "/" + self.image_request
        join = "&" if "?" in path else "?"
        return (f"http://{self.host_ip}:{self.host_port}{path}{join}fps={self.fps}"
                f"&compression={self.compression}")

    def source_name(self):
        return f'network camera "{self.stream_url()}"'

    def open_reader(self):
        return open_stream(self.stream_url(), self.timeout)

    def configure(self):
        if not self.host_ip and "://" not in self.image_request:
            raise ValueError("NetworkCamera needs host_ip")
        super().configure()

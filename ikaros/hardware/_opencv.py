"""The OpenCV import of the camera helpers, with the install hint when it is missing."""


def opencv():
    """The ``cv2`` module, or an ImportError that says how to install it."""
    try:
        import cv2
    except ImportError:
        raise ImportError("this needs OpenCV: pip install 'ikaros[vision]' (or pip install "
                          "opencv-python-headless)") from None
    return cv2

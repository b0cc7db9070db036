"""Vision modules: image filters, edges and features, attention, colour, motion, tracking,
faces, depth and cameras, built on OpenCV (``pip install 'ikaros[vision]'``)."""

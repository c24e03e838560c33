// Nothing of its own: the layering checks (cmake/layers.cmake) link a whole
// target into a shared object built around this file.

"""Output: arrays -> files. Atomic writes and the image encoders (PNG, JPEG, WebP; the
animated formats and frame sequences; the bytes for stdout). Knows pixels and files, nothing
of XAML; the API and the command line call it with what the renderer made."""

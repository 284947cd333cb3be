"""The animation clock (wpf3d.md section 8): pure functions from timelines and a time to values.

It knows WPF's timing rules (clock.py), easing functions (easing.py), key frames (keyframes.py)
and value interpolation (interpolate.py); nothing of XML or pixels. The reader resolves what an
animation targets and builds the Scene at t from the values computed here.
"""

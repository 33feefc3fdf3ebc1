"""Progress of a trimlab call in Blender's window manager (progress_begin, update, end).
A trimlab progress callback reports (stage, done, total) per stage; the bar shows the
fraction of the current stage."""


class WindowProgress:
    def __init__(self, context):
        self.wm = context.window_manager

    def __enter__(self):
        self.wm.progress_begin(0, 1000)
        return self

    def __call__(self, stage, done, total):
        self.wm.progress_update(int(1000 * done / total) if total else 0)

    def __exit__(self, *exc):
        self.wm.progress_end()
        return False

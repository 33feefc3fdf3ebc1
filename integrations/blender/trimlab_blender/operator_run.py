"""One call of the trimlab module from an operator: the module imported, Blender's
progress bar shown while it works, and its errors (trimlab.Error, a missing module, the
user's cancel) turned into the operator's report instead of a traceback."""

from .module_path import import_trimlab
from .progress import WindowProgress


def run_reporting(operator, context, work):
    """Returns work(trimlab, progress), or None after reporting why it failed."""
    try:
        trimlab = import_trimlab(context)
        with WindowProgress(context) as progress:
            return work(trimlab, progress)
    except ImportError as error:
        operator.report({"ERROR"}, str(error))
    except Exception as error:  # trimlab.Error and the user's cancel alike
        operator.report({"ERROR"}, f"TrimLab: {error}")
    return None

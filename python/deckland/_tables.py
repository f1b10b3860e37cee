"""Tables: a pandas DataFrame when pandas is installed, else a dict of numpy arrays."""

from __future__ import annotations

from typing import Any, Dict

import numpy as np

#: Set to False to get dicts of numpy arrays even with pandas installed.
use_pandas = True


def table(columns: Dict[str, np.ndarray]) -> Any:
    """``columns`` (name → numpy array, in order) as a DataFrame if pandas is installed
    and :data:`use_pandas` is true, else as they are."""
    if use_pandas:
        try:
            import pandas
        except ImportError:
            return columns
        return pandas.DataFrame(columns, copy=False)
    return columns

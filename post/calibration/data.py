"""The calibration's input files: CSV with a header and '#' comment lines, numbers checked, and the
error (DataError) that names the file, the line and what is wrong."""
import csv
import math


class DataError(Exception):
    """Bad input: the message names the file, the row and what is wrong."""


# ---------------------------------------------------------------------------------------------
# reading CSV files

def data_rows(path):
    """(line number, row dict) of a CSV with '#' comment lines."""
    try:
        lines = open(path).read().splitlines()
    except OSError as e:
        raise DataError("%s: cannot read (%s)" % (path, e.strerror))
    numbered = [(n + 1, line) for n, line in enumerate(lines) if line.strip() and not line.lstrip().startswith("#")]
    if not numbered:
        raise DataError("%s: no header and no rows" % path)
    header = [h.strip() for h in next(csv.reader([numbered[0][1]]))]
    rows = []
    for n, line in numbered[1:]:
        values = [v.strip() for v in next(csv.reader([line]))]
        if len(values) != len(header):
            raise DataError("%s, line %d: %d values for the %d columns of the header (%s)"
                            % (path, n, len(values), len(header), ",".join(header)))
        rows.append((n, dict(zip(header, values))))
    return header, rows


def number(path, n, row, column):
    try:
        return float(row[column])
    except ValueError:
        raise DataError("%s, line %d: %s = '%s' is not a number" % (path, n, column, row[column]))


def positive_number(path, n, row, column):
    value = number(path, n, row, column)
    if not math.isfinite(value) or value <= 0.0:
        raise DataError("%s, line %d: %s = %s must be positive and finite" % (path, n, column, row[column]))
    return value

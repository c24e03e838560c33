"""The grid of a sweep: keys of a problem file, each with values, every combination one task.

On the command line a setting is ``KEY=V1,V2,...`` with each value written as in the file (TOML:
``0.5``, ``"[-1, 1]"``, ``[1, 2]``); the commas inside brackets, braces and quotes belong to the
values. In Python the values are Python objects (numbers, strings, lists, booleans), written as TOML.
"""
import itertools
import json


class TomlText(str):
    """A value already written as TOML (the command line's), set as it is."""


def toml_value(x):
    """The TOML text of a Python value: 0.5 -> '0.5', 'a' -> '"a"', [1, 2] -> '[1, 2]', True -> 'true'."""
    if isinstance(x, TomlText):
        return str(x)
    if isinstance(x, bool):
        return "true" if x else "false"
    if isinstance(x, (int, float)):
        if x != x or x in (float("inf"), float("-inf")):
            return {"nan": "nan", "inf": "inf", "-inf": "-inf"}[repr(x)]
        return repr(x)
    if isinstance(x, str):
        return json.dumps(x)
    if isinstance(x, (list, tuple)):
        return "[" + ", ".join(toml_value(v) for v in x) + "]"
    raise TypeError(f"a swept value must be a number, a string, a boolean or a list of them, got {type(x).__name__}")


def split_values(text, where):
    """'0.5,"[-1, 1]",[1,2]' -> ['0.5', '"[-1, 1]"', '[1,2]']: the commas outside brackets, braces and quotes."""
    values, depth, quote, start = [], 0, None, 0
    for i, c in enumerate(text):
        if quote:
            if c == quote and text[i - 1] != "\\":
                quote = None
        elif c in "\"'":
            quote = c
        elif c in "[{":
            depth += 1
        elif c in "]}":
            depth -= 1
        elif c == "," and depth == 0:
            values.append(text[start:i].strip())
            start = i + 1
    values.append(text[start:].strip())
    if quote or depth != 0 or any(v == "" for v in values):
        raise ValueError(f"{where}: found the values {text!r}, expected values separated by commas, "
                         "each as written in the file (unclosed quotes and brackets, empty values refused)")
    return values


def parse_setting(text):
    """'KEY=V1,V2' -> (KEY, ['V1', 'V2']) (TOML texts); ValueError saying what is wrong."""
    key, eq, values = text.partition("=")
    if not eq or not key.strip():
        raise ValueError(f"--set: found {text!r}, expected KEY=V1,V2,... (e.g. constraint[8].time_error=0.1,0.2)")
    return key.strip(), split_values(values, f"--set {key.strip()}")


def grid(settings):
    """Every combination of {key: [TOML texts]} as a list of {key: text}, the first key varying slowest."""
    keys = list(settings)
    for k in keys:
        if not settings[k]:
            raise ValueError(f"sweep: the key {k!r} has no value")
    return [dict(zip(keys, combo)) for combo in itertools.product(*(settings[k] for k in keys))]

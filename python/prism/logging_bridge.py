"""Status messages of every device go to the Python logger "prism"."""

import logging

from . import _native

logger = logging.getLogger("prism")

_LEVELS = {
    1: logging.CRITICAL,  # fatal error
    2: logging.ERROR,
    3: logging.WARNING,
    4: logging.WARNING,   # performance warning
    5: logging.INFO,
    6: logging.DEBUG,
}


def _forward(severity, code, source_type, message):
    level = _LEVELS.get(severity, logging.INFO)
    if severity == 4:
        message = "performance: " + message
    if logger.isEnabledFor(level):
        logger.log(level, "%s", message,
                   extra={"anari_code": code, "anari_source": source_type})


def install():
    _native.set_status_handler(_forward)


def raise_on_error(on=True):
    """Make a call raise prism.AnariError when the device reports an error
    during it (the message still goes to the log)."""
    _native.raise_on_error(bool(on))

"""The errors a command reports to its user in one line, each with its exit status.

Exit status of every ``symfloat`` command: 0 success; 1 a check failed (a verdict that is not
as declared, an index sum, a duality, a coverage count); 2 bad input or an environment problem
(an unwritable directory, an unusable cache); 130 interrupted (Ctrl-C).  A module that detects
such a condition raises a subclass of :class:`SymfloatError`; the command line prints
``symfloat: <message>`` on stderr and exits with the class's ``exit_code``.
"""
from __future__ import annotations

__all__ = ["SymfloatError", "CheckFailed", "DerivationError", "InputError", "EnvironmentProblem", "EXIT_OK",
           "EXIT_CHECK", "EXIT_INPUT", "EXIT_INTERRUPTED", "quoted"]

EXIT_OK = 0
EXIT_CHECK = 1
EXIT_INPUT = 2
EXIT_INTERRUPTED = 130


def quoted(text, limit: int = 60) -> str:
    r"""*text* in quotation marks as the user typed it (no backslash doubled, as ``repr`` would), on one line
    and cut at *limit* characters.

    >>> print(quoted(r"\infty"), quoted("a" * 80, 10))
    '\infty' 'aaaaaaaaaa…'
    """
    text = " ".join(str(text).split("\n"))
    return "'" + (text if len(text) <= limit else text[:limit] + "…") + "'"


class SymfloatError(Exception):
    """An error with a one-line message for the user and the command's exit status."""

    exit_code = EXIT_CHECK


class CheckFailed(SymfloatError):
    """A self-check of a result failed (index sum, duality, coverage): exit status 1."""

    exit_code = EXIT_CHECK


class DerivationError(SymfloatError):
    """A derivation module that cannot be built or checked (an author's error: a symbol without a
    sampling interval, a claim that is not a chain): exit status 1, naming the module and line."""

    exit_code = EXIT_CHECK


class InputError(SymfloatError, ValueError):
    """Input outside the stated domain of a command: exit status 2."""

    exit_code = EXIT_INPUT


class EnvironmentProblem(SymfloatError, OSError):
    """A directory that cannot be written, an unusable cache: exit status 2."""

    exit_code = EXIT_INPUT

"""Figures as a report prints them (simulator.io.numbers): the error to 2 significant digits, the value
rounded to the same decimal place, thousands grouped, never an exponent, the unit after a no-break space."""

import pytest

from simulator.io.numbers import NBSP, error_decimals, number, plain, with_error


def _read(s: str) -> str:
    return s.replace(NBSP, " ")


@pytest.mark.parametrize(
    "value, stderr, unit, text",
    [
        (22161.3, 736.2, "lx", "22,160 ± 740 lx"),  # the error's 2 digits are tens: the value to tens
        (22161.3, 73.62, "lx", "22,161 ± 74 lx"),
        (0.7312, 0.007362, "", "0.7312 ± 0.0074"),  # the report's "± 0.007362" of old
        (1660.0, 29.95, "lx", "1,660 ± 30 lx"),  # 29.95 rounds to 30 (2 digits: "30", not "30.0")
        (0.2988, 0.0996, "", "0.30 ± 0.10"),  # 0.0996 carries to 0.10: 2 decimals, not 3
        (86.5, 0.1, "%", "86.50 ± 0.10 %"),
        (512.3, 12.4, "lx", "512 ± 12 lx"),
        (-0.001, 0.0004, "", "−0.00100 ± 0.00040"),
        (5.0, 0.0, "lx", "5 lx"),  # an exact figure: no ±
        (0.12, float("nan"), "", "0.12 ± n/a"),  # an unknown error says so
    ],
)
def test_a_value_with_its_error(value, stderr, unit, text):
    assert _read(with_error(value, stderr, unit)) == text


@pytest.mark.parametrize(
    "value, unit, text",
    [(500.0, "lx", "500 lx"), (0.6, "", "0.6"), (12345.6, "lm", "12,346 lm"), (0.61234, "", "0.612"), (2.216e4, "lx", "22,160 lx"),
     (4523.893, "lm", "4,524 lm"), (0.0, "lx", "0 lx"), (1e-5, "", "0.00001"), (float("nan"), "", "n/a")],
)  # fmt: skip
def test_a_value_alone_keeps_three_significant_digits_and_its_whole_digits(value, unit, text):
    assert _read(plain(value, unit)) == text


def test_never_an_exponent_and_the_unit_never_breaks_away():
    for v in (2.216e4, 1.0e7, 3.2e-6):
        for s in (plain(v, "lx"), with_error(v, v / 300, "lx")):
            assert "e+" not in s and "e-" not in s, s
            assert s.endswith(f"{NBSP}lx") and " " not in s, repr(s)  # only no-break spaces
    assert number(-0.0001, 2) == "0.00"  # a rounded −0 reads 0


def test_error_decimals_is_one_minus_the_errors_decade():
    """d = 1 − ⌊log10 s⌋ for 2 significant digits (tens: −1, units: 0, tenths: 1, …)."""
    assert [error_decimals(s) for s in (736.2, 73.6, 7.36, 0.736, 0.0736)] == [-1, 0, 1, 2, 3]

"""Shared paths of the package's tests (run from anywhere: scripts/test-verify runs them)."""

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def root():
    return ROOT

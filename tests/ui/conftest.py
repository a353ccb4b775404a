from __future__ import annotations

import asyncio

import pytest


@pytest.fixture
def drive():
    """Run an async Pilot scenario from a plain test (no asyncio plugin needed)."""
    return asyncio.run

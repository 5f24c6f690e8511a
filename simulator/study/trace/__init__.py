"""Tracing a study: light groups tallied in one pass, chunks of work, their store, resume and distribution."""

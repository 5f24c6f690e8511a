"""The ``probesim`` command line and one module per command."""

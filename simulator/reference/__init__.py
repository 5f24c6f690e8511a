"""Reference physics: closed forms in float64, and the reference cases that
``probesim verify``, ``stability``, ``chart`` and the tests share."""

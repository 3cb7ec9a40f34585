"""pytest set-up: Sage must be fully initialised before sage_dynsym is used."""
import sage.all  # noqa: F401

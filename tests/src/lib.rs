//! Integration tests of the rasterm workspace live in `tests/tests/`.

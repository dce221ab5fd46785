import persson


def test_version():
    assert persson.__version__ == "0.2.0"

"""``python -m dyncli`` and the ``dyncli`` command.

SIGINT is set to end the process with exit 130 and nothing else before
anything heavy is imported (an interrupt during start-up printed a
traceback; click turned a later one into "Aborted!" and exit 1): by the
first lines of the ``dyncli`` package when it is imported as the command
(``python -m dyncli``, the ``dyncli`` script), again here for any other
route to :func:`main`."""

import sys

from dyncli import quiet_interrupts, single_threaded_blas

#: pydantic's module that finds its plugins (the ``pydantic`` entry-point group)
PLUGIN_LOADER = "pydantic.plugin._loader"


def no_pydantic_plugins() -> None:
    """The command runs without pydantic plugins: finding them imports ``importlib.metadata``
    and reads the entry points of every installed distribution when the first model is built,
    about 15 ms of CPU in a closed-form solve of ~230 ms, for plugins that only observe
    validation (docs/cli.md, "Start-up").  Only the command does this; ``import dyncli`` (the
    Python API) leaves pydantic as it is.  A pydantic that asks the stand-in for anything but
    ``get_plugins`` gets its real module, loaded then."""
    if PLUGIN_LOADER in sys.modules:
        return
    import types

    stub = types.ModuleType(PLUGIN_LOADER, "dyncli's stand-in: no pydantic plugins in the command")

    def get_plugins() -> tuple:
        return ()

    def real(name: str):
        if name.startswith("__"):           # the import system asking whether it is a package
            raise AttributeError(name)
        del sys.modules[PLUGIN_LOADER]
        import importlib

        return getattr(importlib.import_module(PLUGIN_LOADER), name)

    setattr(stub, "get_plugins", get_plugins)     # (a module built at run time)
    setattr(stub, "__getattr__", real)
    sys.modules[PLUGIN_LOADER] = stub


def main() -> None:
    quiet_interrupts()
    single_threaded_blas()
    no_pydantic_plugins()
    from dyncli.cli import main as cli_main

    cli_main()


if __name__ == "__main__":  # pragma: no cover
    main()

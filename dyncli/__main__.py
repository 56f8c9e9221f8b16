"""``python -m dyncli`` and the ``dyncli`` command.

SIGINT is set to end the process with exit 130 and nothing else before
anything heavy is imported (an interrupt during start-up printed a
traceback; click turned a later one into "Aborted!" and exit 1): by the
first lines of the ``dyncli`` package when it is imported as the command
(``python -m dyncli``, the ``dyncli`` script), again here for any other
route to :func:`main`."""

from dyncli import quiet_interrupts


def main() -> None:
    quiet_interrupts()
    from dyncli.cli import main as cli_main

    cli_main()


if __name__ == "__main__":  # pragma: no cover
    main()

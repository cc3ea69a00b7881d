"""The ``mansion`` command line (typer); ``app`` is the console-script entry point."""

from mansion.cli.dataset import dataset
from mansion.cli.edit import edit, variants_app
from mansion.cli.evaluate import eval_app, tune_weights
from mansion.cli.export import export
from mansion.cli.main import app
from mansion.cli.tasks import tasks_app

app.add_typer(eval_app, name="eval")
app.command("tune-weights")(tune_weights)
app.add_typer(tasks_app, name="tasks")
app.command("export")(export)
app.command("edit")(edit)
app.add_typer(variants_app, name="variants")
app.command("dataset")(dataset)

__all__ = ["app"]

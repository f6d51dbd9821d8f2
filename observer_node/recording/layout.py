"""The Foxglove layout shipped for the live view and for recordings, built from the topics
and fields of :mod:`.format` and the status frame's signals in the DBC, with the Foxglove
SDK's layout classes (``foxglove.layouts``).

    python -m observer_node.recording.layout > docker/foxglove/chest-observer-layout.json

(a test checks that the shipped file is what this prints).
"""

from __future__ import annotations

import json
import sys

from . import format as fmt

LAYOUT_FILE = "docker/foxglove/chest-observer-layout.json"


def build_layout() -> str:
    """The layout as JSON: CR and CD estimate against the reference, the inputs, and the
    observer's state, validity and fault bits over time."""
    from foxglove import layouts as fl

    from observer_node.dbc import Codec

    status = Codec()["ObserverStatus"]
    faults = [n for n in status.signal_names if n.startswith(("Fault_", "Invalid_"))]
    est, ref, inp = fmt.ESTIMATE, fmt.REFERENCE, fmt.INPUTS
    st = fmt.STATUS_TOPICS["ObserverStatus"]

    def plot(title: str, series: list[tuple[str, str, str]], y_label: str) -> fl.PlotPanel:
        return fl.PlotPanel(title=title, config=fl.PlotConfig(
            paths=[fl.PlotSeries(value=v, label=label, color=c, timestamp_method="receiveTime")
                   for v, label, c in series],
            show_legend=True, y_axis_label=y_label, time_window_mode="automatic"))

    cr = plot("Chest acceleration CR", [(f"{est}.cr_g", "estimate", "#d62728"),
                                        (f"{ref}.cr_g", "reference (measured)", "#000000")],
              "CR [g]")
    cd = plot("Chest deflection CD", [(f"{est}.cd_mm", "estimate", "#d62728"),
                                      (f"{ref}.cd_mm", "reference (measured)", "#000000")],
              "CD [mm]")
    inputs = plot("Inputs", [(f"{inp}.decel_g", "pulse, bias removed [g]", "#1f77b4"),
                             (f"{inp}.brs_count", "BRS [counts]", "#2ca02c")], "")
    states = fl.StateTransitionsPanel(title="Observer state and faults", config=fl.
                                      StateTransitionsConfig(paths=[
        fl.StateTransitionsSeries(value=f"{est}.state", label="state"),
        fl.StateTransitionsSeries(value=f"{est}.valid", label="estimate valid"),
        fl.StateTransitionsSeries(value=f"{est}.running", label="running"),
        *[fl.StateTransitionsSeries(value=f"{st}.{n}", label=n) for n in faults]],
        show_legend=True))
    layout = fl.Layout(content=fl.SplitContainer(direction="row", items=[
        fl.SplitItem(proportion=2, content=fl.SplitContainer(direction="column", items=[
            fl.SplitItem(content=cr), fl.SplitItem(content=cd)])),
        fl.SplitItem(proportion=1, content=fl.SplitContainer(direction="column", items=[
            fl.SplitItem(content=inputs), fl.SplitItem(proportion=2, content=states)]))]))
    return json.dumps(json.loads(layout.to_json()), indent=1)


if __name__ == "__main__":
    sys.stdout.write(build_layout() + "\n")

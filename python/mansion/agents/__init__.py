"""The one home of the LLM client (:mod:`mansion.agents.llm`) and of the agents' prompt templates
(:mod:`mansion.agents.prompts`). Every stage that asks Claude (the planners, the seed planner,
object placement, the T2D text seeds, the scene editor) goes through them; they import only
:mod:`mansion.models` and :mod:`mansion.exceptions`, so any stage may import them as it may the
models. The graphs that run those agents live with their stage (the building's floors fanned out:
:mod:`mansion.building.graph`; the scene editor's ReAct loop: :mod:`mansion.edit.react`)."""

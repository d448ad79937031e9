"""The LLM boundary (DESIGN.md §8): one ChatModel protocol, providers, cache, reply handling."""

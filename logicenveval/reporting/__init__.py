"""Leaderboards (Markdown, HTML) and run comparison."""

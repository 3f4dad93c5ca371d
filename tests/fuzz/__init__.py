"""Bounded fuzz suites (#13): hypothesis, derandomized, with a fixed budget."""

"""Closing the loop on measured data: residual -> missing physical effect -> refit -> report."""

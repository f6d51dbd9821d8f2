"""crash-replay: feed recorded crash tests onto a CAN bus with accurate timing."""

"""wallbsp.level"""

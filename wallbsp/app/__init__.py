"""wallbsp.app"""
